#pragma once
// envdesign's C++ client: asks a running coordinator (envdesign-coordinator) for the optimal
// design of a design problem file, over LCM. Installed with envdesign; in another CMake
// project:
//
//   find_package(envdesign REQUIRED)
//   target_link_libraries(app PRIVATE envdesign::client)
//
//   #include <envdesign/client/client.h>
//   envdesign::client::Options options;
//   options.on_progress = [](const envdesign::client::Progress &p) { ... };
//   envdesign::client::Result r =
//       envdesign::client::run_design_remote("spec.textproto", "udpm://239.255.76.67:7667?ttl=0",
//       options);
//   if (r.exit_code == 0) std::cout << r.json << "\n";
//
// The client reads the spec and the PDDL files it names and sends them inlined in one
// request; it re-sends the request when the coordinator stays silent (a lost datagram),
// says it still waits every 2 s (ENVDESIGN_KEEPALIVE: the coordinator drops requests whose
// client went silent) and cancels it when its own timeout passes. Exit codes are SPEC.md's.

#include <functional>
#include <string>
#include <vector>

// The library exports only what this header declares.
#define ENVDESIGN_CLIENT_API __attribute__((visibility("default")))

namespace envdesign::client {

struct Progress {
    std::string state;         // "queued", "loading", "searching", "done"
    long long done = 0;        // configurations evaluated, abandoned or skipped
    long long total = 0;       // configurations in the search space
    double best_objective = 0; // +inf while there is none
    long long planner_runs = 0;
    long long cache_hits = 0;
    long long evaluations = 0; // planner answers
    int jobs_in_flight = 0;
    int planners = 0;   // planners alive
    double seconds = 0; // since the coordinator took the request
};

struct Options {
    double time_limit_s = -1; // < 0: the spec's time_limit_s; 0: none
    int max_design_size = -1; // < 0: the spec's; 0: no limit
    int ranking = 0;          // the N best designs in the result (0: the best alone)
    bool ranking_all = false; // rank designs with a modification that does not pay for itself too
    std::string search = "witness";  // "witness" | "exhaustive"
    std::string prune = "none";      // "none" | "relevant"
    std::string heuristic = "lmcut"; // "lmcut" | "hmax" | "blind"
    double timeout_s = 0;            // stop waiting (and cancel) after this; 0: never
    double resend_after_s = 3;       // silence after which the request is sent again
    double give_up_after_s = 30;     // silence after which no coordinator is assumed
    // No coordinator's status (it sends one a second) nor answer heard this long after the
    // start: fail at once with "no coordinator on this bus" (exit code 1); 0: do not check.
    double no_coordinator_after_s = 2;
    // Bus keys (deploy/LAN.md); empty: $ENVDESIGN_KEY_FILE, else an unauthenticated bus. A
    // key file that cannot be used is exit code 2.
    std::string key_file;
    // Called on the calling thread for each progress message.
    std::function<void(const Progress &)> on_progress;
    // Polled on the calling thread (every 50 ms); true: cancel the request as a timeout
    // does (the coordinator stops and sends what it has; exit code 4). E.g. after SIGINT.
    std::function<bool()> stop_requested;
};

struct Result {
    int exit_code = 1;  // 0 a design, 2 bad input, 4 time limit or timeout, 1 anything else
    std::string status; // "optimal", "best_found", or "error"
    std::string error;  // status "error": the message ("FILE:LINE:COL: error: ...")
    std::string json;   // SPEC.md's JSON result, one line (empty for "error")
    std::string text;   // what `envdesign design` prints without --json
    // Lines to read beside the answer (also in `json`): the spec's ("FILE:LINE:COL:
    // warning: ..."), and tasks no design can make explicable, with the reason.
    std::vector<std::string> warnings;
};

// Designs `spec_path` on the coordinator at `lcm_url` (empty: LCM's default URL). Never
// throws for bad input or a missing coordinator: that is in the result.
ENVDESIGN_CLIENT_API Result run_design_remote(const std::string &spec_path,
                                              const std::string &lcm_url,
                                              const Options &options = {});

struct StatusOptions {
    double seconds = 2;   // how long to listen (services send their status once a second)
    std::string key_file; // as Options::key_file
};

struct StatusReport {
    // 0 a coordinator was heard, 1 none was ("no coordinator on this bus" in error), 2 a bad
    // URL or key file (error says which).
    int exit_code = 1;
    std::string error;
    int services = 0; // services heard
    std::string text; // a table, one line a service, then its drops
    std::string json; // JSON lines, one object a service
};

// Listens on `lcm_url` (empty: LCM's default URL) for the services' status messages
// (ENVDESIGN_STATUS, services/README.md) for options.seconds; `envdesign status`.
ENVDESIGN_CLIENT_API StatusReport listen_status(const std::string &lcm_url,
                                                const StatusOptions &options = {});

struct WatchOptions {
    double seconds = 0;   // how long to watch; 0: until stop_requested says so
    std::string key_file; // as Options::key_file
    bool json = false;    // JSON lines (one object a message), else one text line a message
    bool status = false;  // also the services' status (once a second each)
    // Polled on the calling thread (every 50 ms); true: stop watching (e.g. after SIGINT).
    std::function<bool()> stop_requested;
};

struct WatchReport {
    int exit_code = 0; // 0 watched until the end, 2 a bad URL or key file, 1 LCM failed
    std::string error;
    long long messages = 0; // lines passed to on_line
};

// Watches `lcm_url` (empty: LCM's default URL) and calls `on_line` on the calling thread for
// every design result (ENVDESIGN_RESULT), progress (ENVDESIGN_PROGRESS), task distribution
// estimate (ENVDESIGN_TASK_DISTRIBUTION) and, with options.status, service status, as it
// arrives: one text line (a result: its summary, several lines) or one JSON object with
// "kind": "result" | "progress" | "distribution" | "status"; `envdesign watch`.
ENVDESIGN_CLIENT_API WatchReport watch_bus(const std::string &lcm_url, const WatchOptions &options,
                                           const std::function<void(const std::string &)> &on_line);

// A progress callback that draws a live line on stderr when it is a terminal (nothing
// otherwise), for Options::on_progress.
ENVDESIGN_CLIENT_API std::function<void(const Progress &)> stderr_progress();

// $LCM_DEFAULT_URL, else "udpm://239.255.76.67:7667?ttl=0".
ENVDESIGN_CLIENT_API std::string default_url();

} // namespace envdesign::client
