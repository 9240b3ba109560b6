#pragma once
// `envdesign plan DOMAIN PROBLEM`: flags in, plan on stdout, statistics on stderr.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct PlanFlags {
    std::string domain;
    std::string problem;
    std::string heuristic = "lmcut";
    double time_limit_s = 0;
    double memory_limit_mb = 0;
    std::string plan_file; // also write the plan here (sas_plan format)
    bool json = false;
};

void add_plan_flags(CLI::App &command, PlanFlags &flags);

// Returns the process exit code (SPEC.md: 0 solved, 2 bad input, 3 unsolvable, 4 limit).
int run_plan(const PlanFlags &flags);

} // namespace envdesign::cli
