#pragma once
// What the service mains share: the common flags (and --config FILE, service/config_file.h),
// logging, the bus, and the loop that runs until SIGINT or SIGTERM, telling systemd it is
// ready and alive (service/systemd_notify.h).

#include "bus/bus.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace envdesign::services {

struct CommonFlags {
    std::string lcm_url; // empty: LCM's default
    std::string name;    // empty: ROLE/HOST/PID
    std::string log_level = "info";
    std::string key_file; // empty: $ENVDESIGN_KEY_FILE, else an unauthenticated bus
    std::string config;   // read by parse_command_line
    bool check_config = false;
};

// Adds --lcm-url, --name, --key-file, --log-level, --config FILE and --check-config.
void add_common_flags(CLI::App &app, CommonFlags &flags);

// The instance name, its logger and its bus; throws bus::BusError if LCM cannot start and
// bus::KeyFileError if the key file is unusable.
struct Service {
    std::string instance;
    std::shared_ptr<spdlog::logger> log;
    std::unique_ptr<bus::Bus> bus;
    std::shared_ptr<const bus::KeyRing> keys; // null on an unauthenticated bus
};
Service open_service(const std::string &role, const CommonFlags &flags);

// What a service's start-up would fail on beyond its flags (a spec that does not load, a
// state directory that cannot be opened), for --check-config; nullopt when nothing.
using StartupCheck = std::function<std::optional<std::string>()>;

// Parses the command line, with the settings of --config FILE before it (flags given on the
// command line win), then runs `check` (which may throw CLI::ParseError too). Returns
// nothing to go on, or the exit code: 0 after --help or --check-config, 2 for bad flags
// (CLI11's message), a bad config file ("FILE:LINE:COL: error: ..." on stderr), or, with
// --check-config, what the LCM URL, the key file or `startup` finds.
std::optional<int> parse_command_line(CLI::App &app, int argc, char **argv,
                                      const std::function<void()> &check = {},
                                      const StartupCheck &startup = {});

// Opens the service as `role` and returns what `run` returns; an exception out of either is
// reported as "envdesign-ROLE: ..." with exit code 1, a URL that is not LCM's or a key file
// that is unusable (unreadable, malformed, readable by others) with 2.
int serve(const std::string &role, const CommonFlags &flags,
          const std::function<int(Service &)> &run);

// Runs `tick` after every bus.handle() (at least every `period_ms`) until SIGINT or SIGTERM.
// Tells systemd READY=1 first, WATCHDOG=1 from the loop, STOPPING=1 at the end (no-ops
// outside systemd). Returns 0, or 1 if LCM failed.
int run_until_signal(Service &service, const std::function<void()> &tick, int period_ms = 20);
// The same with a tick that says how long (ms) the loop may wait for a message before it
// ticks again: a service with work under way asks to be ticked sooner.
int run_until_signal(Service &service, const std::function<int()> &tick);

} // namespace envdesign::services
