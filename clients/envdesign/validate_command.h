#pragma once
// `envdesign validate DOMAIN PROBLEM PLAN`: checks a sas_plan file with the independent
// validator; prints the plan's cost. Exit 0 valid, 1 invalid plan, 2 bad input.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct ValidateFlags {
    std::string domain;
    std::string problem;
    std::string plan;
};

void add_validate_flags(CLI::App &command, ValidateFlags &flags);
int run_validate(const ValidateFlags &flags);

} // namespace envdesign::cli
