#pragma once
// What the service mains share: the common flags, logging, the bus, and the loop that runs
// until SIGINT or SIGTERM.

#include "bus/bus.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>

namespace envdesign::services {

struct CommonFlags {
    std::string lcm_url; // empty: LCM's default
    std::string name;    // empty: ROLE/HOST/PID
    std::string log_level = "info";
};

void add_common_flags(CLI::App &app, CommonFlags &flags);

// The instance name, its logger and its bus; throws bus::BusError if LCM cannot start.
struct Service {
    std::string instance;
    std::shared_ptr<spdlog::logger> log;
    std::unique_ptr<bus::Bus> bus;
};
Service open_service(const std::string &role, const CommonFlags &flags);

// Runs `tick` after every bus.handle() (at least every `period_ms`) until SIGINT or SIGTERM.
// Returns 0, or 1 if LCM failed.
int run_until_signal(Service &service, const std::function<void()> &tick, int period_ms = 20);
// The same with a tick that says how long (ms) the loop may wait for a message before it
// ticks again: a service with work under way asks to be ticked sooner.
int run_until_signal(Service &service, const std::function<int()> &tick);

} // namespace envdesign::services
