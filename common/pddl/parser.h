#pragma once
// PDDL domain and problem files -> the lifted task (task.h).
//
// Accepted: STRIPS, :typing (with either), constants, :negative-preconditions, :equality,
// :action-costs with static numeric functions. Anything else is rejected by name with a
// ParseError at the offending place; nothing is silently misread.

#include "pddl/sexpr.h"
#include "pddl/task.h"

#include <string>

namespace envdesign::pddl {

Domain parse_domain(const SExpr &define, const std::string &file);
// From PDDL text in memory (e.g. a file carried by a bus message); `name` is the file name
// errors give ("domain.pddl:3:7: error: ...").
Domain parse_domain_text(const std::string &text, const std::string &name);
// Reads `path` (pddl/input_file.h) and parses it as parse_domain_text does.
Domain parse_domain_file(const std::string &path);

// The problem is checked against `domain`: every predicate, object and type must exist.
// Its (:domain NAME) must be domain.name or, when given, `other_domain_name` (a human's
// problem may be the robot's own file, naming the robot's domain).
Problem parse_problem(const SExpr &define, const std::string &file, const Domain &domain,
                      const std::string &other_domain_name = "");
Problem parse_problem_text(const std::string &text, const std::string &name, const Domain &domain,
                           const std::string &other_domain_name = "");
Problem parse_problem_file(const std::string &path, const Domain &domain,
                           const std::string &other_domain_name = "");

} // namespace envdesign::pddl
