#pragma once
// The coordinator's view of its planners and of every job it has sent them: which planners
// are alive (heartbeats) and how many jobs each may hold, which planner holds which job,
// and what to (re-)send. No transport: functions return the job_t messages to publish.
//
// Rules:
//   - a job goes to a live planner with a free slot, round robin; with no free slot it
//     waits in a queue and goes out as soon as a slot frees. The queue is fair between
//     clients (fair_share.h): the least used goes first, one below its share before a
//     client not much lighter, and a waiting client gets its slots by withdrawing
//     (take_withdrawals()) jobs of clients over their share or much heavier; the withdrawn
//     job's slot stays taken until its planner lets go of it, then waits anticipate_s for
//     the client it was withdrawn for;
//   - a planner that has been silent for planner_timeout_s, or says it is stopping, is
//     gone: its jobs are queued again (attempt + 1), preferably for another planner;
//   - a job the planner's heartbeat does not list although it was sent lost_after_s before
//     that heartbeat arrived was lost (or its answer was): it is sent again (same job_id);
//   - a job still held after its deadline (max(job_deadline_s, deadline_factor x the longest
//     answer time seen)) is taken from its holder and sent again, preferably to another
//     planner, unless the holder is working (its heartbeats' busy time grows): then the job
//     stays until its own time limit (+ working_grace_s) passes, so that a long search is
//     never run twice at once; the holder's slot stays taken until it answers or stops listing the
//     job (so a planner that lists jobs and never answers soon gets none), and after demote_after
//     missed deadlines in a row it is demoted: it gets jobs only when no other planner has
//     a free slot, until it answers one in time;
//   - while clients contend, an answered job's slot waits anticipate_s for its client's next
//     job (a search sends it a moment later) before another client's job takes it;
//   - an answer counts only from a planner the job was sent to (sent_to());
//   - the first answer to a job wins; later ones are duplicates.
// Thread-safe.

#include "cluster/fair_share.h"
#include "design/model/numbers.h"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace envdesign::cluster {

// A planner's heartbeat period (its --heartbeat; period_ms on the wire is this in ms):
// from 1 ms to an hour (docs/numbers.md).
inline constexpr design::NumberRange HEARTBEAT_PERIOD_S{1e-3, 3600};

// Why a heartbeat from the wire must not be used: no sender, a capacity below 1, a period_ms
// outside HEARTBEAT_PERIOD_S, a busy_seconds that is not finite or is negative (issue 21: a
// NaN one froze the planner's "working" state). nullopt when it may be.
std::optional<std::string> heartbeat_problem(const envdesign::planner_heartbeat_t &beat);

struct PoolConfig {
    double planner_timeout_s = 1.0;
    double lost_after_s = 0.3;
    // Jobs in flight per planner worker: 2 lets a planner start its next job while the
    // answer to the last one travels (the round trip is hidden), at the price of `abandon`
    // seeing answers a job later.
    int jobs_per_slot = 2;
    double job_deadline_s = 5.0; // the least deadline of a job
    double deadline_factor = 4;  // x the longest time a planner took to answer
    int demote_after = 2;        // missed deadlines in a row
    double working_grace_s = 2;  // past a job's time limit, a working holder keeps it this long
    double quantum_s = 2;        // a job runs this long (x2 per withdrawal) before it may yield
    // While clients contend, a slot whose job was answered waits this long for the same
    // client's next job before another client's takes it: a search sends its next jobs a
    // moment after an answer, and without the wait each of them had to withdraw a job again
    // (a planner round trip; issue 21's flood made a 0.05 s request take 1 s).
    double anticipate_s = 0.05;
    // A client's usage of the planners (planner-seconds) halves every usage_half_life_s; one
    // that used less by more than usage_margin_s gets slots first (fair_share.h).
    double usage_half_life_s = 10;
    double usage_margin_s = 2;
};

struct PoolCounters {
    long long jobs_sent = 0;   // sends, re-sends included
    long long jobs_resent = 0; // re-sends
    long long duplicates = 0;  // answers to jobs answered before (or never sent)
    long long planners_joined = 0;
    long long planners_lost = 0;
    long long deadlines_missed = 0; // jobs taken from their holder at their deadline
    long long withdrawn = 0;        // jobs withdrawn for a request that held no slot
    long long planners_demoted = 0;
    std::set<std::string> answered_by; // planners that answered
};

// A job the pool tracks; `owner` is the coordinator's id of the request it serves.
struct JobRecord {
    std::uint64_t owner = 0;
    envdesign::job_t message;
    std::string planner; // holding it; empty while queued
    std::chrono::steady_clock::time_point sent;
    std::set<std::string> tried;
    int preemptions = 0; // times withdrawn for another request (fair_share.h)
};

class PlannerPool {
public:
    using Clock = std::chrono::steady_clock;
    using Events = std::vector<std::string>; // "planner X joined" ..., for the caller's log

    explicit PlannerPool(PoolConfig config) : config_(config) {}

    // The client `owner`'s requests count for in the fair shares (fair_share.h); an owner
    // never named is a client of its own.
    void set_client(std::uint64_t owner, std::uint64_t client);
    // Queues `job` (job_id set by the caller) for `owner`; returns what to publish now.
    std::vector<envdesign::job_t> submit(std::uint64_t owner, envdesign::job_t job,
                                         Clock::time_point now);
    std::vector<envdesign::job_t> heartbeat(const envdesign::planner_heartbeat_t &beat,
                                            Clock::time_point now, Events *events = nullptr);
    // The record of `job_id` if this is its first answer (it is then forgotten); nullopt for
    // a duplicate or a job this pool never sent. `to_send` gets jobs the freed slot takes.
    std::optional<JobRecord> answer(std::int64_t job_id, const std::string &from,
                                    std::vector<envdesign::job_t> &to_send, Clock::time_point now);
    // Jobs withdrawn from their planners since the last call (publish them on WITHDRAW).
    std::vector<envdesign::job_t> take_withdrawals();
    // Planners silent too long are gone; returns the resends.
    std::vector<envdesign::job_t> expire(Clock::time_point now, Events *events = nullptr);
    // Forgets jobs (their request ended or stopped waiting for them); those held by a
    // planner are withdrawn (take_withdrawals()) and keep their slot until it lets go.
    void forget(const std::vector<std::int64_t> &job_ids);
    // Forgets everything about `owner`'s jobs.
    void forget_owner(std::uint64_t owner);

    // False if `job_id` is outstanding and was never sent to `planner` (an answer from it is
    // not to be taken); true otherwise (an unknown job's answer is a duplicate anyway).
    bool sent_to(std::int64_t job_id, const std::string &planner) const;
    // The kind of an outstanding job, to check its answer against.
    std::optional<std::int8_t> kind_of(std::int64_t job_id) const;
    int capacity() const; // job slots of the live planners
    int live_planners() const;
    bool demoted(const std::string &planner) const;
    double deadline_s() const; // what a job sent now has
    int jobs_in_flight(std::uint64_t owner) const;
    int jobs_in_flight() const; // of every owner
    PoolCounters counters() const;
    // The counters of `owner`'s jobs alone (planners joined and lost stay 0).
    PoolCounters counters(std::uint64_t owner) const;

private:
    struct Planner {
        int slots = 1;
        int holding = 0;
        Clock::time_point last_beat;
        std::map<std::int64_t, Clock::time_point> overdue; // taken at their deadline: when sent
        int misses = 0;                                    // deadlines in a row
        bool demoted = false;
        double busy_seconds = 0;     // as its last heartbeat said (running jobs included)
        Clock::time_point busy_grew; // when that last grew
        bool working(Clock::time_point now) const;
        // Taken for another client (its slot is that client's once let go of; 0: a forgotten
        // job's, no one's), not yet let go of.
        std::map<std::int64_t, std::uint64_t> withdrawn;
        int workers = 1; // its capacity: jobs it runs at once
        // A slot kept for this client's next job until then (anticipate_s).
        std::uint64_t kept_for = 0;
        Clock::time_point kept_until{};
        // A free slot; while clients contend (`contended`), jobs are not queued behind a
        // running one in the planner (a fair share would then wait there): one per worker.
        bool free(bool contended) const {
            int taken = holding + static_cast<int>(overdue.size() + withdrawn.size());
            return taken < (contended ? workers : slots);
        }
    };

    std::vector<envdesign::job_t> assign(Clock::time_point now);
    FairShare::View fair_view(bool contended, Clock::time_point now) const;
    std::uint64_t client_of(std::uint64_t owner) const;
    std::deque<std::int64_t>::iterator next_fair(bool contended, Clock::time_point now);
    void keep_for(Planner &planner, std::uint64_t client, Clock::time_point now);
    std::deque<std::int64_t>::iterator kept_job(bool contended, Clock::time_point now);
    void withdraw_for_waiting(Clock::time_point now, bool contended);
    void withdraw(std::int64_t job_id, std::uint64_t taker, Clock::time_point now);
    void withdraw_queued(const std::string &planner);
    bool overdue(const JobRecord &record, Clock::time_point now) const;
    std::optional<std::string> pick_planner(const JobRecord &record, bool contended,
                                            Clock::time_point now);
    bool contended() const; // jobs of more than one client are queued or held
    void requeue(std::int64_t job_id);
    void release(JobRecord &record);
    void drop_planner(const std::string &name, Events *events, const char *why);
    void remember_answered(std::int64_t job_id, std::uint64_t owner);
    void take_overdue(Clock::time_point now, Events *events);
    void note_answer_time(const std::string &from, std::int64_t job_id, const JobRecord *record,
                          Clock::time_point now);
    Clock::duration deadline() const;

    PoolConfig config_;
    mutable std::mutex mutex_;
    std::map<std::string, Planner> planners_;
    std::string last_pick_; // round robin: the next pick comes after this name
    std::map<std::int64_t, JobRecord> jobs_;
    std::deque<std::int64_t> queue_;
    PoolCounters counters_;
    std::map<std::uint64_t, PoolCounters> owners_;
    // Recently answered jobs and their owners, so that duplicates count for their request.
    std::map<std::int64_t, std::uint64_t> answered_;
    std::deque<std::int64_t> answered_order_;
    double longest_answer_s_ = 0;
    FairShare fair_{config_.quantum_s, config_.usage_half_life_s, config_.usage_margin_s};
    std::map<std::uint64_t, std::uint64_t> clients_; // owner -> client (set_client)
    std::vector<envdesign::job_t> withdrawals_;
};

} // namespace envdesign::cluster
