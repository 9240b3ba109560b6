#pragma once
// Fair shares of the planners between clients (planner_pool.h's queue): a client of many
// long jobs must not hold every planner slot while another waits (issue 21: forty requests
// that never end starved every other client). The unit is the client: with bus keys the
// process that sent the requests (forty names from one process are one client), else the
// client's name; its requests share its part.
//
//   - Next out: the oldest queued job of the client that holds the fewest slots, then has
//     had the least planner time (least attained service): a new client goes first.
//   - Preemption: a client with a queued job that holds less than its share (the slots over
//     the clients with work, at least 1) takes a slot from a client holding more than its
//     share at once: that client's longest-running job is withdrawn and queued again. When
//     every client holds its share, a client holding none takes a turn from the youngest job
//     past its quantum of the client holding the most (then the longest served). A job's
//     quantum doubles each time it is withdrawn (quantum_s x 2^n), so a long search still
//     ends once the others are served.
//
//   FairShare fair(2.0);
//   std::size_t i = fair.next(queued_clients, held);              // index into queued_clients
//   auto job = fair.victim(queued_clients, running, held, slots); // a job to withdraw, or none

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace envdesign::cluster {

class FairShare {
public:
    using Held = std::map<std::uint64_t, int>; // jobs held by planners, by client

    struct Running {
        std::int64_t job = 0;
        std::uint64_t client = 0;
        double seconds = 0; // since it was sent
        int preemptions = 0;
    };

    explicit FairShare(double quantum_s) : quantum_s_(quantum_s) {}

    // Planner time `client` had; past MAX_CLIENTS clients the least served is forgotten.
    void add_service(std::uint64_t client, double seconds);
    static constexpr std::size_t MAX_CLIENTS = 4096;

    // The index in `queued` (the clients of the queued jobs, oldest job first) of the job to
    // send next; `queued` is not empty.
    std::size_t next(const std::vector<std::uint64_t> &queued, const Held &held) const;

    // A client's share of `slots`: the slots over the clients with queued or running jobs.
    static int share(const std::vector<std::uint64_t> &queued, const std::vector<Running> &running,
                     int slots);

    // A job of `running` to withdraw for a client in `queued` below its share of `slots`;
    // none when no such client waits or no job may yield.
    std::optional<std::int64_t> victim(const std::vector<std::uint64_t> &queued,
                                       const std::vector<Running> &running, const Held &held,
                                       int slots) const;

private:
    struct Key {
        int held;
        double service;
        bool operator<(const Key &o) const {
            return held != o.held ? held < o.held : service < o.service;
        }
    };
    Key key(std::uint64_t client, const Held &held) const;
    std::optional<std::int64_t> turn(const std::vector<std::uint64_t> &queued,
                                     const std::vector<Running> &running, const Held &held) const;

    double quantum_s_;
    std::map<std::uint64_t, double> service_; // planner seconds each client's jobs took
};

} // namespace envdesign::cluster
