#pragma once
// `envdesign evaluate SPEC --design NAME[,NAME...]`: a proposed design evaluated the way the
// search evaluates designs, printed as `envdesign design` prints its answer (status
// "evaluated"), with the empty design as the baseline and the same explanation.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct EvaluateFlags {
    std::string spec;
    std::string design; // comma-separated modification names; empty: the empty design
    bool design_given = false;
    bool json = false;
    int workers = 1;
    double time_limit_s = -1; // < 0: the spec's time_limit_s
    std::string heuristic = "lmcut";
};

void add_evaluate_flags(CLI::App &command, EvaluateFlags &flags);

// Returns 0 (evaluated), 2 bad input (a name that is not a modification of the spec: named
// on stderr), 4 the time limit stopped the evaluation.
int run_evaluate(const EvaluateFlags &flags);

} // namespace envdesign::cli
