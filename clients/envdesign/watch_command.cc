#include "watch_command.h"

#include "cli_error.h"
#include "service/number_flag.h"

#include <envdesign/client/client.h>

#include <atomic>
#include <csignal>
#include <iostream>

namespace envdesign::cli {
namespace {

// Set by SIGINT/SIGTERM only: watching ends cleanly (exit 0), output flushed.
std::atomic<bool> stop_watching{false};
extern "C" void on_stop(int) { stop_watching = true; }

} // namespace

void add_watch_flags(CLI::App &command, WatchFlags &flags) {
    command.add_option("--lcm-url,--connect", flags.lcm_url,
                       "LCM URL of the bus (default: $LCM_DEFAULT_URL, else "
                       "udpm://239.255.76.67:7667?ttl=0)");
    command.add_option("--key-file", flags.key_file,
                       "bus keys (default: $ENVDESIGN_KEY_FILE; deploy/LAN.md)");
    command.add_option("--seconds", flags.seconds, "stop after S seconds (0: at Ctrl-C)")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    command.add_flag("--json", flags.json,
                     "one JSON object a line for every message (in text a result takes several "
                     "lines)");
    command.add_flag("--status", flags.status, "also the services' status (once a second each)");
}

int run_watch(const WatchFlags &flags) {
    std::signal(SIGINT, on_stop);
    std::signal(SIGTERM, on_stop);
    client::WatchOptions options;
    options.seconds = flags.seconds;
    options.key_file = flags.key_file;
    options.json = flags.json;
    options.status = flags.status;
    options.stop_requested = [] { return stop_watching.load(); };
    // Flushed a line at a time: a pipe (`| jq`) sees each message when it passes.
    client::WatchReport report = client::watch_bus(
        flags.lcm_url, options, [](const std::string &line) { std::cout << line << std::endl; });
    if (report.exit_code != 0)
        throw CommandError(report.exit_code, report.error);
    return 0;
}

} // namespace envdesign::cli
