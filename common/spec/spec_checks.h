#pragma once
// The checks of a design problem that need the loaded models: every edit is read and
// applied, modification by modification, to every task (design_spec.h runs these with
// Checks::FULL).

#include "design/design_problem.h"
#include "spec/spec_reader.h"

#include <string>

namespace envdesign::spec {

// Reads one edit of the spec; `field` is its path ("modification[0].edit[1]") for messages.
// Throws pddl::ParseError when the edit sets no kind or its text is not an S-expression.
design::Edit edit_from_proto(const proto::Edit &edit, const std::string &field,
                             const SpecFile &spec);

// Applies each modification on its own, STRICT, to every task's robot and/or human model,
// and compiles and grounds every task's unmodified pair; throws pddl::ParseError at the
// edit (or task) at fault.
// A remove is an error only when no task has what it removes.
void check_design_problem(const design::DesignProblem &problem, const SpecFile &spec);

} // namespace envdesign::spec
