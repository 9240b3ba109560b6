#pragma once
// A spec_t (a spec file with its PDDL files inlined, as a client sends it) -> a DesignProblem,
// on the coordinator (Checks::FULL) and on every planner (Checks::TRUSTED_BY_HASH: the
// coordinator checked these very bytes). Everything is read from the message in memory; no
// file is written. Error messages name the client's files: the spec's name and, for a PDDL
// file, the path the spec writes, relative to the spec's directory.

#include "design/design_problem.h"
#include "envdesign/spec_t.hpp"
#include "spec/design_spec.h"

namespace envdesign::spec {

// Throws pddl::ParseError ("FILE:LINE:COL: error: ...") for bad input, including a path the
// spec names that `spec` does not carry ("the request does not carry 'x' (robot_domain)", at
// that field).
design::DesignProblem load_spec(const envdesign::spec_t &spec, Checks checks);

} // namespace envdesign::spec
