#pragma once
// `envdesign design SPEC`: the optimal environment design of a design problem file.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct DesignFlags {
    std::string spec;
    bool json = false;
    int workers = 1;
    double time_limit_s = -1; // < 0: the spec's time_limit_s
    int max_design_size = -1; // < 0: the spec's max_design_size
    std::string search = "witness";
    int ranking = 0;          // the N best designs (0: the best alone)
    bool ranking_all = false; // padded designs in the ranking too (design/search/ranking.h)
    std::string prune = "none";
    std::string heuristic = "lmcut";
    std::string connect;  // LCM URL of a running coordinator; --workers does not apply then
    std::string key_file; // with connect: bus keys (empty: $ENVDESIGN_KEY_FILE)
};

void add_design_flags(CLI::App &command, DesignFlags &flags);

// Returns the exit code: 0 a design (optimal, or best found under --prune), 2 bad input or
// usage, 3 every design's objective is infinite (proven), 4 the time limit stopped the search
// (the best design found is still printed).
int run_design(const DesignFlags &flags);

} // namespace envdesign::cli
