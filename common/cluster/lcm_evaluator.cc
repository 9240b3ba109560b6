#include "cluster/lcm_evaluator.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/explicability.h"
#include "envdesign/evaluation_t.hpp"
#include "wire/job_messages.h"

#include <algorithm>

namespace envdesign::cluster {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

} // namespace

LcmEvaluator::LcmEvaluator(const design::DesignProblem &problem, JobRouter &router,
                           RemoteRequest request, const std::atomic<bool> &cancelled,
                           double grace_s)
    : problem_(problem), router_(router), request_(std::move(request)), cancelled_(cancelled),
      grace_s_(grace_s), robot_bounds_(design::asks_robot_bounds(problem)),
      ie_floors_(design::ie_floors_hold(problem)), owner_(router.open(inbox_, request_.client)) {}

LcmEvaluator::~LcmEvaluator() { router_.close(owner_); }

void LcmEvaluator::evaluate(const std::vector<design::ConfigurationEvaluation> &configurations,
                            const design::Deadline &deadline,
                            const design::EvaluationCallbacks &callbacks) {
    design::Dispatcher dispatcher(configurations, static_cast<int>(problem_.tasks.size()),
                                  robot_bounds_, ie_floors_, callbacks,
                                  design::behaviour_of(problem_.weights.behaviour).may_explain);
    Batch batch{configurations, dispatcher, {}};
    std::optional<Clock::time_point> give_up_at;
    while (true) {
        if (!give_up_at)
            send_jobs(batch, deadline);
        in_flight_ = static_cast<int>(batch.in_flight.size());
        if (batch.in_flight.empty())
            break;
        if (auto answer = inbox_.pop_until(Clock::now() + std::chrono::milliseconds(50)))
            take(batch, *answer);
        if (!give_up_at && (cancelled_ || error_))
            give_up_at = Clock::now();
        else if (!give_up_at && deadline.expired())
            give_up_at = Clock::now() + seconds(grace_s_); // planners stop at it too
        if (give_up_at && Clock::now() >= *give_up_at) {
            give_up(batch);
            break;
        }
    }
    in_flight_ = 0;
    if (error_)
        throw *error_;
    dispatcher.finish_rest();
}

design::EvaluatorCounters LcmEvaluator::counters() const { return counters_; }

void LcmEvaluator::send_jobs(Batch &batch, const design::Deadline &deadline) {
    while (static_cast<int>(batch.in_flight.size()) < window() && !deadline.expired() &&
           !cancelled_) {
        auto job = batch.dispatcher.next_job();
        if (!job)
            return;
        envdesign::job_t message = wire::job_message(
            *job, batch.configurations[job->configuration].configuration, request_.request_id,
            request_.spec_hash, request_.heuristic, deadline);
        batch.in_flight[router_.send(owner_, std::move(message))] = {*job, Clock::now()};
    }
}

void LcmEvaluator::take(Batch &batch, const envdesign::evaluation_t &answer) {
    auto it = batch.in_flight.find(answer.job_id);
    if (it == batch.in_flight.end())
        return; // of an earlier batch that stopped waiting for it
    design::Job job = it->second.job;
    double round_trip = std::chrono::duration<double>(Clock::now() - it->second.at).count();
    transport_seconds_ += std::max(0.0, round_trip - answer.seconds - answer.queued_seconds);
    job_seconds_ += answer.seconds;
    batch.in_flight.erase(it);
    ++answers_;
    if (job.kind == design::JobKind::EXPLICABILITY)
        ++counters_.task_evaluations;
    counters_.planner_runs += answer.planner_runs;
    counters_.cache_hits += answer.cache_hits;
    counters_.groundings_skipped += answer.groundings_skipped;
    counters_.planner_seconds += answer.planner_seconds;
    if (answer.status == envdesign::evaluation_t::STATUS_BAD_INPUT ||
        answer.status == envdesign::evaluation_t::STATUS_ERROR) {
        bool bad_input = answer.status == envdesign::evaluation_t::STATUS_BAD_INPUT;
        if (!error_)
            error_.emplace(bad_input ? 2 : 1,
                           bad_input ? answer.error
                                     : "planner " + answer.sender + " failed: " + answer.error);
        return;
    }
    design::JobAnswer taken = wire::job_answer(job, answer);
    if (sink_)
        sink_(batch.configurations[job.configuration].configuration, taken);
    batch.dispatcher.receive(std::move(taken));
}

// Stops waiting: every job still out counts as out of time.
void LcmEvaluator::give_up(Batch &batch) {
    std::vector<std::int64_t> ids;
    for (const auto &[id, sent] : batch.in_flight) {
        ids.push_back(id);
        if (!error_)
            batch.dispatcher.receive(design::JobAnswer{sent.job, std::nullopt, std::nullopt, {}});
    }
    batch.in_flight.clear();
    router_.forget(ids);
}

int LcmEvaluator::window() const { return std::max(1, router_.pool().capacity()); }

} // namespace envdesign::cluster
