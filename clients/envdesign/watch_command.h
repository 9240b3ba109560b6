#pragma once
// `envdesign watch`: prints the design results, progress and task distribution estimates
// on a bus as they pass, as text or JSON lines (the C++ client library's watch_bus does the
// work), until --seconds pass or Ctrl-C.

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct WatchFlags {
    std::string lcm_url;  // empty: LCM's default URL
    std::string key_file; // empty: $ENVDESIGN_KEY_FILE
    double seconds = 0;   // 0: until Ctrl-C
    bool json = false;
    bool status = false;
};

void add_watch_flags(CLI::App &command, WatchFlags &flags);

// Returns the exit code: 0 (after --seconds or Ctrl-C), 2 a bad URL or key file, 1 LCM failed.
int run_watch(const WatchFlags &flags);

} // namespace envdesign::cli
