#pragma once
// An independent plan checker on the lifted task (like VAL): it simulates the plan with
// ground atoms as strings, sharing no code with the grounder or the search, so the tests
// and the design engine's self-checks catch a wrong plan whatever produced it.

#include "pddl/task.h"

#include <string>
#include <vector>

namespace envdesign::validate {

struct Validation {
    bool valid = false;
    long long cost = 0;   // the plan's metric value (steps when the problem has no metric)
    int failed_step = -1; // 0-based index of the offending step, -1 if none
    std::string error;    // why it is invalid, naming the step and the atom
    // When every step applied (valid, or only the goal missing): the cost of the steps and
    // the atoms true after the last one, sorted (tests follow states with these).
    long long executed_cost = 0;
    std::vector<std::string> final_state;
};

// `plan` holds actions as "(name obj ...)".
Validation validate_plan(const pddl::Domain &domain, const pddl::Problem &problem,
                         const std::vector<std::string> &plan);

// Reads a plan in the sas_plan format: one "(action args)" a line, ';' comments ignored.
// Throws pddl::ParseError if the file cannot be read or a line is not an action.
std::vector<std::string> read_plan_file(const std::string &path);

} // namespace envdesign::validate
