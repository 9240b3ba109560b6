#pragma once
// The planner service's core (services/planner): does the jobs addressed to it on
// ENVDESIGN_JOB with `workers` threads and answers on ENVDESIGN_EVALUATION; announces
// itself, its capacity and the jobs it holds on ENVDESIGN_HEARTBEAT, and its status (jobs
// held and done, answers remembered, drops) on ENVDESIGN_STATUS once a second. Stateless as far as
// the system is concerned: any planner can do any job, and one may start or stop at any
// time; what it keeps (specs, its plan caches, recent answers) only saves work.
//
//   - A job naming a spec it lacks waits while the planner asks the job's coordinator for
//     it (ENVDESIGN_SPEC_NEED, again every need_retry_s); after park_limit_s it is dropped
//     (the coordinator has long sent it elsewhere).
//   - A job it holds already is a duplicate and ignored; one it answered lately (the answer
//     was lost) is answered again from memory.
//   - Answers are also remembered by content (answer_memory.h): a job whose spec, kind,
//     heuristic, task and configuration were answered lately is answered at once, whoever
//     sends it (a restarted coordinator re-sends what it had in flight); one whose content
//     is being worked on waits for that answer instead of computing it again.
//   - Each worker has its own plan cache per spec, so a job's counters are its own.
//   - A job withdrawn on ENVDESIGN_WITHDRAW (its coordinator gave the slot to another
//     request) stops at once and is not answered; its heartbeats count running jobs' time,
//     so coordinators see it working.
//
//   Planner planner(bus, config);
//   while (running) { bus.handle(20ms); planner.tick(); }
//   planner.stop();   // a last heartbeat says it is going; running jobs stop at once (their
//                     // coordinators send them elsewhere), so SIGTERM ends it within a second

#include "bus/bus.h"
#include "bus/status.h"
#include "cluster/answer_memory.h"
#include "cluster/planner_specs.h"
#include "concurrency/blocking_queue.h"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"

#include <atomic>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <thread>

namespace envdesign::cluster {

struct PlannerConfig {
    std::string instance;
    int workers = 1;
    double heartbeat_period_s = 0.2;
    double need_retry_s = 0.3;
    double park_limit_s = 30; // a job whose spec never comes is dropped after this
    int max_specs = 4;
    int answers_kept = 4096;         // by job id, for re-sent jobs
    int remembered_answers = 16'384; // by content (answer_memory.h), each about a plan's size
    SpecLimits spec_limits;          // what chunks from the bus may make it hold
    // The planner's resident memory stays under workers x this: a job's search may hold
    // (A*'s registry, per-state data, open list) this less its share of what the process
    // holds when the job's evaluator is made (job_search_budget, planner_memory.h); a job
    // that needs more is answered LIMIT.
    std::size_t job_memory_bytes = std::size_t{1} << 30;
};

struct PlannerStats {
    long long jobs_done = 0;
    long long answers_repeated = 0;   // answers sent again from memory (same job id)
    long long answers_remembered = 0; // jobs answered by content, without computing
    long long duplicates = 0;         // jobs received while held
    double busy_seconds = 0;
};

class Planner {
public:
    Planner(bus::Bus &bus, PlannerConfig config);
    ~Planner(); // stops and joins the workers (running jobs finish first)

    void tick(); // bus thread
    void stop(); // takes no more jobs and says so
    PlannerStats stats() const;

private:
    using Clock = std::chrono::steady_clock;
    struct Pending {
        envdesign::job_t job;
        Clock::time_point received;
    };

    void on_job(const envdesign::job_t &job);
    void on_chunk(const envdesign::spec_chunk_t &chunk);
    void on_withdraw(const envdesign::job_t &job);
    void abandon(const envdesign::job_t &job);
    void ask_for_specs(Clock::time_point now);
    void drop_stale_parked(Clock::time_point now);
    void heartbeat(bool stopping);
    void guard_memory();
    void fill_status(envdesign::service_status_t &status) const;
    void work();
    envdesign::evaluation_t evaluate(const Pending &pending, class WorkerCaches &caches,
                                     const std::atomic<bool> *stop);
    // Bookkeeping after `job`'s answer was published; returns the answers of the jobs that
    // waited for the same content, to publish and then release().
    std::vector<envdesign::evaluation_t> answered(const envdesign::job_t &job,
                                                  const envdesign::evaluation_t &answer);
    void release(const std::vector<envdesign::evaluation_t> &answers);
    void remember_by_id(const envdesign::evaluation_t &answer);

    bus::Bus &bus_;
    PlannerConfig config_;
    PlannerSpecs specs_;
    mutable std::mutex mutex_; // guards what follows; queue_ locks itself, inside mutex_
    // Jobs ready for a worker. Closed when the planner goes: the workers drain it.
    concurrency::BlockingQueue<Pending> queue_;
    std::map<std::string, std::vector<Pending>> parked_; // by spec hash
    std::map<std::string, std::pair<std::string, Clock::time_point>>
        asked_; // hash -> coordinator, when
    std::set<std::int64_t> held_;
    std::map<std::int64_t, envdesign::evaluation_t> answers_;
    std::deque<std::int64_t> answer_order_;
    AnswerMemory memory_;
    // Content -> jobs waiting for it; a key is present while its first job (the one that
    // computes) is queued, parked or running.
    std::map<std::string, std::vector<envdesign::job_t>> followers_;
    PlannerStats stats_;
    std::atomic<bool> stopping_{false};
    std::atomic<bool> cancelled_{false}; // after stop(): running searches end as at a limit
    struct Running {
        Clock::time_point start;
        std::shared_ptr<std::atomic<bool>> stop; // withdrawn or stopping: the search ends
        bool over_memory = false;                // stopped at the memory limit: answered LIMIT
    };
    std::map<std::int64_t, Running> running_;    // by job id, under mutex_
    std::size_t idle_resident_ = 0;              // the process with no job running, under mutex_
    std::set<std::int64_t> withdrawn_;           // taken back as a worker popped them, under mutex_
    std::atomic<Clock::time_point> last_beat_{}; // workers beat too (a withdrawn job let go)
    Clock::time_point last_tick_{};
    bus::StatusPublisher status_;
    std::vector<std::thread> workers_;
    std::vector<bus::Subscription> subscriptions_;
};

} // namespace envdesign::cluster
