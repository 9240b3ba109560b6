#pragma once
// One active coordinator per bus (issue 10). Every coordinator publishes its status once a
// second (bus/status.h), with the wall-clock time it started (`started_utime`). A coordinator
// is outranked by another that started earlier, or at the same microsecond and has the lower
// signed sender id (bus keys: bus/auth.h; without keys, the lower instance name); the order
// is the same seen from every coordinator, since these travel with the status. Another
// coordinator with this one's own name is a peer like any other (a status is this one's own
// only if its start and sender id are too), so two clusters started with the same --name on
// one bus do not both answer: the later stands by and says why. A coordinator is
//   DISCOVERING  for `discovery_s` after it starts: it takes requests but starts none and
//                says nothing to clients (its refusals wait: coordinator.h), so that it
//                hears the others before it works or answers (the status period is 1 s);
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

    // `sender_id`: this process's signed sender id on the bus (0 without keys).
    Election(std::string instance, std::int64_t started_utime, ElectionConfig config,
             Clock::time_point now, std::uint64_t sender_id = 0);

    // A status heard on ENVDESIGN_STATUS from bus sender `sender_id` (0 without keys); only
    // other coordinators' count.
    void heard(const envdesign::service_status_t &status, Clock::time_point now,
               std::uint64_t sender_id = 0);
    // The role at `now`, and a line saying why if it changed since the last call.
    std::optional<std::string> update(Clock::time_point now);
    Role role() const { return role_; }
    // The coordinator this one stands by for (empty unless STANDBY).
    const std::string &active() const { return active_; }

private:
    struct Peer { // a coordinator process: names may repeat, starts and sender ids do not
        std::int64_t started_utime;
        std::uint64_t sender_id;
        std::string name;
        auto operator<=>(const Peer &) const = default;
    };
    bool outranks(const Peer &peer) const;

    std::string instance_;
    std::int64_t started_utime_;
    std::uint64_t sender_id_;
    ElectionConfig config_;
    Clock::time_point discovered_; // the end of discovery
    Role role_;
    std::string active_;
    std::map<Peer, Clock::time_point> peers_; // when each was last heard
};

} // namespace envdesign::cluster
