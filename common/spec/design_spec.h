#pragma once
// A design problem file (SPEC.md, "Design problem file") -> a checked DesignProblem.
//
// Paths in the file are relative to it. Everything is checked here, once, so that the
// search never meets bad input: the PDDL files parse, every task's models compile, each
// modification applies on its own to every task (unknown actions, predicates, objects or
// parameters, wrong arities, and removes of what no task has are errors), probabilities
// are non-negative with a positive sum, weights are in range.
//
// Errors are pddl::ParseError "SPEC:LINE:COL: error: ..." naming the field at fault; an
// error inside a PDDL file names that file, with a note naming the spec line that refers
// to it.

#include "design/design_problem.h"
#include "design/spec_reader.h"

#include <optional>
#include <string>

namespace envdesign::design {

DesignProblem load_design_problem(const std::string &spec_path);

// "SPEC:LINE:COL: warning: the task probabilities sum to 1.1, not 1; they were normalised
// to a 0.545455, b 0.454545" when the probabilities written in `spec` do not sum to 1;
// nothing when they do, when no task writes one, or when they are bad input (negative, not
// finite, a zero sum: load_design_problem says so). load_design_problem keeps it in
// DesignProblem::warnings; a client of a coordinator asks here.
std::optional<std::string> probability_warning(const SpecFile &spec);

// From a spec already read (e.g. received over the bus); relative paths are resolved
// against the directory of spec.path.
DesignProblem load_design_problem(const SpecFile &spec);

} // namespace envdesign::design
