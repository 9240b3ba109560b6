#pragma once
// `envdesign explicable`: the most explicable plan of one robot/human model pair.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct ExplicableFlags {
    std::string robot_domain;
    std::string human_domain; // empty: the robot's domain
    std::string problem;
    std::string human_problem; // empty: `problem`
    std::string distance = "EXP_COST_DIFF";
    std::string heuristic = "lmcut";
    double time_limit_s = 0;
    bool json = false;
};

void add_explicable_flags(CLI::App &command, ExplicableFlags &flags);

// Returns the exit code: 0 a most explicable plan, 2 bad input, 3 none (IE infinite),
// 4 time limit.
int run_explicable(const ExplicableFlags &flags);

} // namespace envdesign::cli
