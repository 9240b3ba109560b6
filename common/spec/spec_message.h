#pragma once
// A spec_t (a spec file with its PDDL files inlined) -> a checked DesignProblem, on the
// coordinator and on every planner. The design engine reads PDDL from files, so the inlined
// files are written to a fresh directory under `work_dir`, the spec's path fields are pointed
// at them, the problem is loaded (design_spec.h: every check of a local run) and the
// directory is removed. Error messages name the client's files, not the temporary ones.

#include "design/design_problem.h"
#include "envdesign/spec_t.hpp"

#include <string>

namespace envdesign::cluster {

// Throws pddl::ParseError ("FILE:LINE:COL: error: ...") for bad input, including a path the
// spec names that `spec` does not carry; std::runtime_error when `work_dir` is not writable.
design::DesignProblem load_spec(const envdesign::spec_t &spec, const std::string &work_dir);

// The default work directory: $TMPDIR, else /tmp.
std::string default_work_dir();

} // namespace envdesign::cluster
