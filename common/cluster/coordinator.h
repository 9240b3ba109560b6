#pragma once
// The coordinator service's core (services/coordinator): takes design requests on
// ENVDESIGN_REQUEST, runs each one's design search on its own thread (request_run.h) with
// jobs sent to the planners (job_router.h), and publishes ENVDESIGN_PROGRESS and
// ENVDESIGN_RESULT. Requests are named by (client, request_id): a repeat of an open request
// gets its progress, a repeat of a finished one its result again (kept keep_results_s).
// At most max_active requests search at once; the others wait in order, at most max_waiting
// of them and at most max_per_client open per client: beyond that a request is answered at
// once with a "busy" error (exit code 1) and not kept, so that the client may send it again
// later. Progress keep-alives go only to searching requests (a waiting one hears progress
// when its client repeats it). A request its client stopped asking for (no keepalive_t nor
// repeat from the sending process for client_timeout_s: the client was killed) is dropped:
// a searching one is cancelled and its planner jobs withdrawn, a waiting one forgotten.
//
//   bus::Bus bus(url, logger);
//   Coordinator coordinator(bus, config);
//   int wait = 0;
//   while (running) { bus.handle(wait ms); wait = coordinator.tick(); }
//
// Its status (bus/status.h) goes out once a second, idle or not: requests open and waiting,
// live planners, jobs in flight, evaluations stored, drops, and its role: one coordinator
// per bus is active, the others stand by and take over when it falls silent (election.h).
// Only the active one says anything to clients: while discovering it takes requests
// silently and holds its refusals (bad input, busy) until it knows it is active, so that a
// request is never answered by two coordinators.
// Handlers and tick() run on the bus thread. Messages that make no sense (bad sizes, unknown
// enums, a request without a client name) are counted in bus.malformed() and logged.

#include "bus/bus.h"
#include "bus/status.h"
#include "cluster/election.h"
#include "cluster/job_router.h"
#include "cluster/request_run.h"
#include "cluster/spec_chunks.h"
#include "cluster/spec_library.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "envdesign/spec_need_t.hpp"

#include <deque>
#include <map>
#include <memory>

namespace envdesign::cluster {

// Why `request` cannot be served (unknown enums, a time limit that is not finite or out of
// its range, a max_design_size above design::DESIGN_SIZE, no spec name, a spec larger than
// max_spec_bytes); nullopt when it can.
std::optional<std::string> request_problem(const envdesign::design_request_t &request,
                                           std::size_t max_spec_bytes);

// The unit a request counts for in admission (max_per_client) and the planners' fair shares:
// the process that sent it when the bus names one (bus::Bus::message_origin: signed with
// keys, declared without), so that forty client names from one process are one client;
// else the client's name.
std::string client_unit(std::uint64_t origin, const std::string &name);

struct CoordinatorConfig {
    std::string instance; // this coordinator's name on the bus
    // Requests searched at once. A search mostly waits for its planners' answers, and the
    // planners are shared fairly between requests (fair_share.h), so this is high: a flood
    // of requests that never end must not keep another client's request from starting.
    int max_active = 64;
    int max_waiting = 64;   // requests waiting for a search slot, from all clients
    int max_per_client = 8; // requests searching or waiting per client_unit, and per name
    // The largest spec a request may carry (its text and files); larger is bad input.
    std::size_t max_spec_bytes = DEFAULT_MAX_SPEC_BYTES;
    PoolConfig pool;
    double grace_s = 1.0;             // after a deadline, LIMIT answers are awaited this long
    double progress_interval_s = 0.1; // progress at most this often per request
    double keepalive_s = 0.5;         // and at least this often while it is open
    double keep_results_s = 600;      // results kept for repeats of a request
    // Every request ends within this (its own limit when smaller): a request without a time
    // limit cannot hold a search slot and planners for ever.
    double max_time_limit_s = 3600;
    // A request whose client said nothing of it (keepalive or repeat) this long is dropped.
    // Clients say so every bus::CLIENT_KEEPALIVE_S, so this allows a few lost messages.
    double client_timeout_s = 10;
    // Task evaluations and bounds kept across requests (evaluation_stores.h), each a plan
    // of a few hundred bytes; 0: none kept.
    std::size_t stored_evaluations = 200'000;
    // Where the stored evaluations are kept across restarts (evaluations.db, SQLite);
    // empty: in memory only. The file holds at most stored_evaluations records and
    // state_max_bytes bytes of them.
    std::string state_dir;
    std::size_t state_max_bytes = std::size_t{1} << 30;
    // fsync every commit: survives power loss too, at ~5 ms a record on a VM disk; without,
    // a record survives the process being killed at any instant (store/record_db.h).
    bool state_sync = false;
    // The bus keys: records are tagged HMAC-SHA256 with the first (empty: a checksum).
    std::vector<std::string> state_secrets;
    ElectionConfig election; // who runs requests when several coordinators share a bus
};

struct CoordinatorStats {
    long long accepted = 0; // distinct requests taken
    long long repeats = 0;  // repeats of a known request
    long long results = 0;  // results published (repeats included)
    long long busy = 0;     // requests refused as busy
    long long dropped = 0;  // requests dropped: their client stopped asking
    int open = 0;           // searching or waiting
};

class Coordinator {
public:
    Coordinator(bus::Bus &bus, CoordinatorConfig config);
    ~Coordinator(); // cancels and joins the open requests

    // Returns how long (ms) the caller may wait for messages before the next tick: short
    // while requests are open, so that a finished search is published at once.
    int tick();
    CoordinatorStats stats() const;
    const JobRouter &router() const { return router_; }
    Role role() const { return election_.role(); }

private:
    using Clock = std::chrono::steady_clock;
    struct Open {
        std::unique_ptr<RequestRun> run;
        bool started = false;
        Clock::time_point last_progress{};
        envdesign::design_progress_t last_sent{};
        std::uint64_t client_origin = 0; // the bus sender of the request (0: no keys)
        std::string client;              // its unit of admission and fair shares
        Clock::time_point heard;         // the client's last keepalive or repeat
        bool dropped = false;            // cancelled for its client's silence
    };
    struct Closed {
        envdesign::design_result_t result;
        Clock::time_point at;
    };

    void on_request(const envdesign::design_request_t &request);
    std::optional<std::string> busy(const std::string &client, const std::string &sender) const;
    void on_cancel(const envdesign::cancel_t &cancel);
    void on_keepalive(const envdesign::keepalive_t &keepalive);
    void drop_silent(Clock::time_point now);
    void on_spec_need(const envdesign::spec_need_t &need);
    void start_waiting();
    void close_finished();
    void note_change(const envdesign::design_request_t &request,
                     envdesign::design_result_t &result);
    void publish_progress(Open &open, Clock::time_point now, bool force);
    void answer(envdesign::design_result_t result);
    void publish_result(envdesign::design_result_t result);
    void fill_status(envdesign::service_status_t &status) const;
    void report_bad_records();
    void elect(Clock::time_point now);

    bus::Bus &bus_;
    CoordinatorConfig config_;
    JobRouter router_;
    SpecLibrary specs_;
    EvaluationStores stores_;
    std::map<std::string, Open> open_;
    std::deque<std::string> waiting_;
    Clock::time_point last_tick_{};
    long long bad_records_reported_ = 0; // the state file's rejected records, logged
    std::map<std::string, Closed> closed_;
    std::vector<envdesign::design_result_t> held_; // refusals while discovering (answer())
    // The last design per (client, spec name) of requests with a reason: their `change`.
    std::map<std::string, std::vector<std::string>> last_designs_;
    mutable std::mutex stats_mutex_;
    CoordinatorStats stats_;
    bus::StatusPublisher status_;
    Election election_;
    std::vector<bus::Subscription> subscriptions_; // last: handlers stop before the rest goes
};

} // namespace envdesign::cluster
