#pragma once
// Health you can see (issue 11): every service publishes an envdesign::service_status_t on
// ENVDESIGN_STATUS once a second, idle or not, so that lcm-spy, `envdesign status` and
// clients can tell a service that is up from one that is not. StatusPublisher fills in what
// the bus knows (version, uptime, malformed messages, handler errors, authentication drops
// per channel and reason); the service adds its own numbers. StatusBoard keeps the last
// status of every service process heard: by name and start, so that two processes with one
// name (two clusters started alike on one bus) are two entries, not one.
//
//   bus::StatusPublisher status(bus, "coordinator", instance);
//   status.tick([&](envdesign::service_status_t &s) { s.planners = ...; });  // bus thread
//
//   bus::StatusBoard board(bus);            // a listener
//   while (...) bus.handle(50ms);
//   if (board.heard("coordinator")) ...

#include "bus/bus.h"
#include "envdesign/service_status_t.hpp"

#include <chrono>
#include <compare>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace envdesign::bus {

// envdesign's version (CMake's PROJECT_VERSION).
std::string version();

// Appends one drop counter (channel, reason, count) to `status`.
void add_drop(envdesign::service_status_t &status, const std::string &channel,
              const std::string &reason, long long count);

class StatusPublisher {
public:
    using Fill = std::function<void(envdesign::service_status_t &)>;
    static constexpr double PERIOD_S = 1.0;

    // `kind`: "coordinator", "planner" or "bridge"; the clock of uptime starts here.
    StatusPublisher(Bus &bus, std::string kind, std::string instance, double period_s = PERIOD_S);

    // Publishes a status if a period has passed since the last one (the first at once);
    // `fill` adds the service's numbers. Returns true if it published. Bus thread.
    bool tick(const Fill &fill);
    // The status tick() would publish now, without publishing it.
    envdesign::service_status_t snapshot(const Fill &fill) const;
    // The wall clock when this publisher was made (the service's start), microseconds.
    std::int64_t started_utime() const { return started_utime_; }

private:
    using Clock = std::chrono::steady_clock;
    Bus &bus_;
    std::string kind_;
    std::string instance_;
    double period_s_;
    Clock::time_point started_ = Clock::now();
    std::int64_t started_utime_;
    Clock::time_point last_{};
    bool sent_ = false;
};

// A service process on the bus: its name and the wall-clock microsecond it started. Names
// may repeat (--name is the operator's); a process's start does not change.
struct ServiceId {
    std::string name;
    std::int64_t started_utime = 0;
    auto operator<=>(const ServiceId &) const = default;
};

// The last status of each service process heard on a bus. Bus thread.
class StatusBoard {
public:
    explicit StatusBoard(Bus &bus);

    // By name, then start.
    const std::map<ServiceId, envdesign::service_status_t> &services() const { return last_; }
    // True once a service of `kind` was heard.
    bool heard(const std::string &kind) const;
    // The names heard from more than one process, each with how many, in name order.
    std::map<std::string, int> repeated_names() const;

private:
    std::map<ServiceId, envdesign::service_status_t> last_;
    Subscription subscription_;
};

} // namespace envdesign::bus
