#pragma once
// `envdesign status`: the services on a bus, from their status messages (ENVDESIGN_STATUS).

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct StatusFlags {
    std::string connect;  // LCM URL (empty: $LCM_DEFAULT_URL, else LCM's default)
    std::string key_file; // bus keys (empty: $ENVDESIGN_KEY_FILE)
    double seconds = 2;   // listening time
    bool json = false;    // JSON lines instead of a table
};

void add_status_flags(CLI::App &command, StatusFlags &flags);

// Prints every service heard; returns 0 if a coordinator was heard, 1 if none was ("no
// coordinator on this bus" on stderr), 2 for a bad URL or key file.
int run_status(const StatusFlags &flags);

} // namespace envdesign::cli
