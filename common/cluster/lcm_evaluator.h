#pragma once
// The Evaluator (design/evaluation/evaluator.h) of the networked coordinator: the same Dispatcher
// as the in-process LocalEvaluator, with jobs sent to planner services through a JobRouter instead
// of to threads. Jobs in flight are capped by the planners' free slots, so that `abandon` sees
// answers as early as in-process.
//
// Faults are the router's business (re-sends, duplicates); this class only stops waiting:
// once the deadline passed it gives planners `grace_s` to answer LIMIT, and on cancel it
// stops at once; every job still out then counts as LIMIT, so every configuration of the
// batch is reported. A planner's BAD_INPUT or ERROR answer ends the search (RemoteError).

#include "cluster/job_router.h"
#include "design/design_problem.h"
#include "design/evaluation/dispatcher.h"
#include "design/evaluation/evaluator.h"

#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

namespace envdesign::cluster {

// A planner could not evaluate a job: exit_code 2 (the modified models are bad input) or 1.
class RemoteError : public std::runtime_error {
public:
    RemoteError(int exit_code, const std::string &message)
        : std::runtime_error(message), exit_code_(exit_code) {}
    int exit_code() const { return exit_code_; }

private:
    int exit_code_;
};

// What every job of one request carries.
struct RemoteRequest {
    std::int64_t request_id = 0;
    std::string spec_hash;
    std::int8_t heuristic = 0;
    std::string client; // the unit of the planners' fair shares (JobRouter::open)
};

class LcmEvaluator : public design::Evaluator {
public:
    // `problem`, `router` and `cancelled` must outlive the evaluator; evaluate() runs on one
    // thread at a time. Set `cancelled` and call wake() to stop a running evaluate().
    LcmEvaluator(const design::DesignProblem &problem, JobRouter &router, RemoteRequest request,
                 const std::atomic<bool> &cancelled, double grace_s = 1.0);
    ~LcmEvaluator() override;

    void evaluate(const std::vector<design::ConfigurationEvaluation> &batch,
                  const design::Deadline &deadline,
                  const design::EvaluationCallbacks &callbacks) override;
    design::EvaluatorCounters counters() const override;

    void wake() { inbox_.wake(); }
    // Called with every answer as it arrives, before the search sees it (a durable store
    // keeps it there: design/evaluation/stored_evaluator.h); same thread as evaluate().
    using AnswerSink =
        std::function<void(const design::Configuration &, const design::JobAnswer &)>;
    void on_answer(AnswerSink sink) { sink_ = std::move(sink); }
    // Sends, re-sends, duplicates and planners of this evaluator's jobs.
    PoolCounters transport() const { return router_.pool().counters(owner_); }
    long long answers() const { return answers_.load(); }
    // Summed over answers: round trip less the planner's time on the job, queue included
    // (what the network and the coordinator add).
    double transport_seconds() const { return transport_seconds_; }
    // Summed over answers: the planners' wall time on the jobs.
    double job_seconds() const { return job_seconds_; }
    int in_flight() const { return in_flight_.load(); }

private:
    struct Sent {
        design::Job job;
        std::chrono::steady_clock::time_point at;
    };
    struct Batch {
        const std::vector<design::ConfigurationEvaluation> &configurations;
        design::Dispatcher &dispatcher;
        std::map<std::int64_t, Sent> in_flight;
    };

    void send_jobs(Batch &batch, const design::Deadline &deadline);
    void take(Batch &batch, const envdesign::evaluation_t &answer);
    void give_up(Batch &batch);
    int window() const;

    const design::DesignProblem &problem_;
    JobRouter &router_;
    RemoteRequest request_;
    const std::atomic<bool> &cancelled_;
    double grace_s_;
    bool robot_bounds_;
    bool ie_floors_;
    Inbox inbox_;
    std::uint64_t owner_;
    design::EvaluatorCounters counters_;
    std::optional<RemoteError> error_;
    AnswerSink sink_;
    double transport_seconds_ = 0;
    double job_seconds_ = 0;
    std::atomic<long long> answers_{0};
    std::atomic<int> in_flight_{0};
};

} // namespace envdesign::cluster
