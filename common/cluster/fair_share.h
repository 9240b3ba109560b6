#pragma once
// Fair shares of the planners between clients (planner_pool.h's queue): a client of many
// long jobs must not hold every planner slot while another waits (issue 21: forty requests
// that never end starved every other client), and a client that used the planners little
// lately gets them first. The unit is the client (client_unit, coordinator.h): the process
// that sent the requests (signed with bus keys, declared without: forty names from one
// process are one client), else the client's name; its requests share its part.
//
// A client's usage is the planner-seconds its jobs took, halved every half_life_s (as a Unix
// or fair-share scheduler decays CPU usage), plus the seconds its running jobs have run so
// far. "Much lighter" means less usage by more than margin_s: the margin keeps two clients of
// nearly equal usage from taking slots back and forth.
//
//   - Next out: the oldest queued job of the client with the least usage; but a client
//     holding less than its share (the slots over the clients with work, at least 1) goes
//     first unless the least used client is much lighter than it.
//   - Preemption (victim()), first rule that applies:
//       1. a client below its share takes a slot from a client above it, unless that client
//          is much lighter: the longest-running job of the client holding the most;
//       2. the least used waiting client takes a slot from a client much heavier than it:
//          that client's longest-running job that may yield, i.e. was never withdrawn or has
//          run past its quantum (quantum_s x 2^withdrawals). A newcomer to a flood gets every
//          slot it asks for at once, and a long search still ends: each job yields at most
//          once before its quantum, and the quantum doubles with each withdrawal;
//       3. when every client holds its share, a client holding none takes a turn from the
//          youngest job past its quantum of the client holding the most (then the most used).
//     A withdrawn job's slot is the taker's (incoming) until its planner lets go of it.
//
//   FairShare fair(2.0);
//   FairShare::View view{queued_clients, running, incoming, slots, now};
//   std::size_t i = fair.next(view);       // index into queued_clients
//   auto taken = fair.victim(view);        // a job to withdraw and for whom, or none

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace envdesign::cluster {

class FairShare {
public:
    using Clock = std::chrono::steady_clock;
    using Counts = std::map<std::uint64_t, int>; // by client

    struct Running {
        std::int64_t job = 0;
        std::uint64_t client = 0;
        double seconds = 0; // since it was sent
        int preemptions = 0;
    };
    // The pool at one moment.
    struct View {
        std::vector<std::uint64_t> queued; // the clients of the queued jobs, oldest job first
        std::vector<Running> running;      // jobs held by planners
        Counts incoming;                   // slots on the way to a client (withdrawn for it)
        int slots = 1;                     // job slots of the live planners
        Clock::time_point now;
    };
    struct Taken {
        std::int64_t job;     // to withdraw
        std::uint64_t client; // whose slot it becomes
    };

    explicit FairShare(double quantum_s, double half_life_s = 10, double margin_s = 2)
        : quantum_s_(quantum_s), half_life_s_(half_life_s), margin_s_(margin_s) {}

    // Planner time `client` had (a job answered or withdrawn) at `now`; past MAX_CLIENTS
    // clients the least used is forgotten.
    void add_service(std::uint64_t client, double seconds, Clock::time_point now);
    static constexpr std::size_t MAX_CLIENTS = 4096;
    // The client's decayed usage at `now`, its running jobs in `running` included.
    double usage(std::uint64_t client, const std::vector<Running> &running,
                 Clock::time_point now) const;

    // The index in view.queued (not empty) of the job to send next.
    std::size_t next(const View &view) const;
    // A client's share of `slots`: the slots over the clients with queued or running jobs.
    static int share(const std::vector<std::uint64_t> &queued, const std::vector<Running> &running,
                     int slots);
    // A job of view.running to withdraw and the client its slot goes to; none when no
    // waiting client may take one.
    std::optional<Taken> victim(const View &view) const;

private:
    struct Client {
        double usage = 0;
        int held = 0;    // running jobs, plus slots on the way
        int waiting = 0; // queued jobs no slot is on the way for
    };
    std::map<std::uint64_t, Client> clients(const View &view) const;
    bool much_lighter(const Client &a, const Client &b) const {
        return a.usage + margin_s_ < b.usage;
    }
    bool may_yield(const Running &r) const; // never withdrawn, or past its quantum
    bool past_quantum(const Running &r) const;
    std::optional<Taken> over_share(const View &view, const std::map<std::uint64_t, Client> &all,
                                    int fair) const;
    std::optional<Taken> much_heavier(const View &view,
                                      const std::map<std::uint64_t, Client> &all) const;
    std::optional<Taken> turn(const View &view, const std::map<std::uint64_t, Client> &all) const;

    struct Used {
        double usage = 0;
        Clock::time_point at; // when `usage` was this
    };
    double decayed(const Used &used, Clock::time_point now) const;

    double quantum_s_;
    double half_life_s_;
    double margin_s_;
    std::map<std::uint64_t, Used> used_; // planner seconds each client's jobs took, decaying
};

} // namespace envdesign::cluster
