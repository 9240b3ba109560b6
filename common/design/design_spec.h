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

#include <string>

namespace envdesign::design {

DesignProblem load_design_problem(const std::string &spec_path);

// From a spec already read (e.g. received over the bus); relative paths are resolved
// against the directory of spec.path.
DesignProblem load_design_problem(const SpecFile &spec);

} // namespace envdesign::design
