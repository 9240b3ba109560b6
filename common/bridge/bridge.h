#pragma once
// Overview: envdesign-bridge's core (services/bridge/main.cc is its thin main, README.md
// there the user's view). It is handed its transport (a Bus), its arrivals (an
// ArrivalSource: DDS in deployment, an ArrivalQueue in tests) and its clock (clock.h), so
// tests run it in-process over memq:// with scripted arrivals and a hand-set time.
//
//   ArrivalSource --(reader thread, or pump())--> ArrivalTracker (common/arrivals: checks, estimate
//   of D per design problem, drift detector)
//     --> ENVDESIGN_TASK_DISTRIBUTION: each problem's estimate (lcm-spy shows it)
//     --> on drift or a new task: ENVDESIGN_REEVALUATE (the request, same type) and a
//         re-evaluation by a RedesignBackend (redesigns.h): in this process, or by
//         envdesign-coordinator through ENVDESIGN_REQUEST
//   ENVDESIGN_RESULT <-- the new design, with what changed and why; its D becomes the
//   reference the drift detector compares the estimate with.
//   --redesign local: every change of an estimate (at most every reweigh_interval_s) is
//   also re-weighed over the stored evaluations (no planner); when that proves another
//   design optimal it is published at once; when it needs evaluations the store lacks, a
//   re-evaluation is asked for at once (tracker.h, unevaluated).
//
// Threads: the reader thread (config.reader_thread; else the caller's pump()) takes samples and
// feeds the tracker; the bus thread (the one calling bus.handle() and tick()) takes results; the
// local backend has its own worker. One mutex guards the tracker; LCM publishing is thread-safe
// (bus.h). Bad samples are counted and logged through a LogThrottle; nothing a sample holds can
// throw out of the reader thread.
//
//   dds::ArrivalReader reader(domain);
//   SystemClock clock;
//   Bridge bridge(bus, config, reader, clock);   // loads specs, asks for the first designs
//   while (running) { bus.handle(20ms); bridge.tick(); }

#include "bridge/clock.h"
#include "bridge/messages.h"
#include "bridge/redesigns.h"

#include "arrivals/arrival_source.h"
#include "arrivals/tracker.h"
#include "bus/bus.h"

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace envdesign::bridge {

enum class Mode { LOCAL, COORDINATOR };

struct ProblemSource {
    std::string id;        // as the arrivals name it
    std::string spec_path; // its design problem file
};

struct BridgeConfig {
    std::string instance; // the bridge's name on the bus
    std::vector<ProblemSource> problems;
    arrivals::TrackerConfig tracker;
    Mode mode = Mode::LOCAL;
    double publish_hz = 10;                // estimates per problem per second, at most
    bool reader_thread = true;             // false: the caller takes arrivals with pump()
    arrivals::RedesignOptions local;       // Mode::LOCAL
    CoordinatorRequestOptions coordinator; // Mode::COORDINATOR
};

struct BridgeStats {
    arrivals::IntakeCounters intake;
    long long requests = 0; // re-evaluations asked for (the initial ones included)
    long long answers = 0;
    long long reweighs = 0;            // re-weightings answered
    long long reweigh_changes = 0;     // of those, new designs published
    long long reweigh_planning = 0;    // of those, needing evaluations the store lacks
    long long new_tasks_held_back = 0; // every problem's, beyond its new-task bounds
};

class Bridge {
public:
    // Throws pddl::ParseError for a spec that does not load. `bus`, `source` and `clock`
    // must outlive the bridge.
    Bridge(bus::Bus &bus, BridgeConfig config, arrivals::ArrivalSource &source, const Clock &clock);
    ~Bridge(); // stops the reader thread and the backend

    // Waits up to `wait_s` for arrivals and takes what is there; returns how many. Only
    // without config.reader_thread (it would race the thread).
    std::size_t pump(double wait_s);
    void tick(); // bus thread: estimates of problems whose arrivals paused
    BridgeStats stats() const;
    // The design in force for `problem_id`, as last published (throws for an unknown id).
    DesignInForce design(const std::string &problem_id) const;

private:
    void read_arrivals(); // the reader thread
    std::size_t take_batch(std::vector<arrivals::Arrival> &batch);
    // The rest run with mutex_ held.
    void receive(const arrivals::Arrival &arrival, double now, std::int64_t now_utime);
    void log_rejected(const arrivals::Arrival &arrival, const arrivals::Outcome &outcome,
                      double now);
    void send(const arrivals::Request &request);
    void reweigh(double now);
    void on_reweighed(const Answer &answer);
    void publish_estimate(const std::string &id, double now, bool force);
    void on_answer(Answer answer);
    double now() const;

    bus::Bus &bus_;
    BridgeConfig config_;
    arrivals::ArrivalSource &source_;
    const Clock &clock_;
    mutable std::mutex mutex_;
    arrivals::ArrivalTracker tracker_;
    arrivals::LogThrottle throttle_;
    arrivals::LogThrottle skew_throttle_;      // accepted arrivals with a skewed clock
    arrivals::LogThrottle held_back_throttle_; // new tasks beyond their bounds
    struct Published {
        DesignInForce design;
        double at = -1e9;         // last estimate sent
        long long estimated = -1; // the problem's estimated count then
    };
    std::map<std::string, Published> problems_;
    std::int64_t next_request_id_ = 0;
    long long requests_ = 0;
    long long answers_ = 0;
    long long reweighs_ = 0, reweigh_changes_ = 0, reweigh_planning_ = 0;
    std::unique_ptr<RedesignBackend> backend_;
    LocalRedesigns *local_ = nullptr;          // backend_ in Mode::LOCAL: it can re-weigh
    std::optional<bus::Subscription> results_; // optional: bus.h's default constructor
    std::optional<bus::Subscription> progress_;
    // needs a type only bus.cc sees
    std::atomic<bool> stopping_{false};
    std::thread reader_thread_; // last: starts once everything else exists
};

} // namespace envdesign::bridge
