#pragma once
// One active coordinator per bus (issue 10). Every coordinator publishes its status once a
// second (bus/status.h), with the wall-clock time it started (`started_utime`). A coordinator
// is outranked by another that started earlier, or at the same microsecond and has the lower
// instance name; the order is the same seen from every coordinator, since both numbers travel
// in the status. A coordinator is
//   DISCOVERING  for `discovery_s` after it starts: it takes requests but starts none, so
//                that it hears the others before it works (the status period is 1 s);
//   STANDBY      while it has heard an outranking coordinator within `takeover_after_s`: it
//                takes no requests (the active one answers them), keeps its planner list
//                warm from heartbeats, and drops what it had open when it steps down (the
//                outranking one was up earlier, so it heard those requests too);
//   ACTIVE       otherwise; so a standby takes over `takeover_after_s` after the active
//                one's last status, and a restarted coordinator (a later start) stands by.
// Starts are compared across machines by their wall clocks: keep them in step (NTP). With
// bus keys only key holders can send a status, so an outsider cannot make one stand by.
//
//   Election election(instance, started_utime, {1.5, 3.0}, now);
//   on each coordinator status heard: election.heard(status, now);
//   on each tick: if (auto change = election.update(now)) ... log *change
//
// Not thread-safe: the bus thread calls it.

#include "envdesign/service_status_t.hpp"

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace envdesign::cluster {

struct ElectionConfig {
    // Seconds after the start before it may run requests. 0 (the library's default, for a
    // coordinator alone on memq://): at once; envdesign-coordinator uses 1.5.
    double discovery_s = 0;
    double takeover_after_s = 3; // silence of the outranking coordinator before a takeover
};

enum class Role { DISCOVERING, ACTIVE, STANDBY };
const char *to_string(Role role);

class Election {
public:
    using Clock = std::chrono::steady_clock;

    Election(std::string instance, std::int64_t started_utime, ElectionConfig config,
             Clock::time_point now);

    // A status heard on ENVDESIGN_STATUS; only other coordinators' count.
    void heard(const envdesign::service_status_t &status, Clock::time_point now);
    // The role at `now`, and a line saying why if it changed since the last call.
    std::optional<std::string> update(Clock::time_point now);
    Role role() const { return role_; }
    // The coordinator this one stands by for (empty unless STANDBY).
    const std::string &active() const { return active_; }

private:
    struct Peer {
        std::int64_t started_utime;
        Clock::time_point heard;
    };
    bool outranks(const std::string &name, const Peer &peer) const;

    std::string instance_;
    std::int64_t started_utime_;
    ElectionConfig config_;
    Clock::time_point discovered_; // the end of discovery
    Role role_;
    std::string active_;
    std::map<std::string, Peer> peers_;
};

} // namespace envdesign::cluster
