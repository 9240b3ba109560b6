#include "cluster/request_run.h"

#include "bus/channels.h"
#include "bus/codec.h"
#include "bus/log.h"
#include "cluster/lcm_evaluator.h"
#include "cluster/spec_chunks.h"
#include "design/design_run.h"
#include "design/evaluation/evaluation_log.h"
#include "design/evaluation/stored_evaluator.h"
#include "pddl/parse_error.h"
#include "spec/spec_message.h"
#include "wire/job_messages.h"

#include <algorithm>
#include <optional>

namespace envdesign::cluster {
namespace {

using envdesign::design_progress_t;
using envdesign::design_request_t;

constexpr std::size_t COORDINATOR_PLAN_BYTES = std::size_t{256} << 20; // per search

} // namespace

RequestRun::RequestRun(RunContext context, design_request_t request)
    : context_(std::move(context)), request_(std::move(request)),
      name_(bus::request_name(request_.sender, request_.request_id)) {
    progress_.request_id = request_.request_id;
    progress_.client = request_.sender;
    progress_.state = design_progress_t::STATE_QUEUED;
    progress_.best_objective = design::INF;
}

RequestRun::~RequestRun() {
    cancel();
    if (thread_.joinable())
        thread_.join();
}

void RequestRun::start() {
    thread_ = std::thread([this] { run(); });
}

void RequestRun::cancel() {
    cancelled_ = true;
    std::lock_guard lock(mutex_);
    if (evaluator_)
        evaluator_->wake();
}

design_progress_t RequestRun::progress() const {
    std::lock_guard lock(mutex_);
    design_progress_t p = progress_;
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - accepted_).count();
    if (evaluator_) {
        p.evaluations = evaluator_->answers();
        p.jobs_in_flight = evaluator_->in_flight();
    }
    return p;
}

envdesign::design_result_t RequestRun::result() const {
    std::lock_guard lock(mutex_);
    return result_;
}

void RequestRun::run() {
    std::string hash;
    auto &log = context_.bus.log();
    try {
        set_state(design_progress_t::STATE_LOADING);
        // The one full check of this spec: planners load these bytes trusting their hash.
        design::DesignProblem problem =
            envdesign::spec::load_spec(request_.spec, envdesign::spec::Checks::FULL);
        std::string bytes = bus::encode_message(request_.spec);
        hash = content_hash(bytes);
        for (const auto &chunk : context_.specs.add(hash, bytes, request_.request_id))
            context_.bus.publish(bus::SPEC, chunk);
        log.info("request {} | spec {} loaded: {} task(s), {} modification(s), {} bytes", name_,
                 hash.substr(0, 12), problem.tasks.size(), problem.modifications.size(),
                 bytes.size());
        set_state(design_progress_t::STATE_SEARCHING);
        search(problem, hash);
    } catch (const pddl::ParseError &e) {
        finish(wire::error_result(2, e.what()));
    } catch (const RemoteError &e) {
        finish(wire::error_result(e.exit_code(), e.what()));
    } catch (const std::bad_alloc &) {
        finish(wire::error_result(4, "out of memory"));
    } catch (const std::exception &e) {
        finish(wire::error_result(1, e.what()));
    }
    if (!hash.empty())
        context_.specs.release(hash);
}

void RequestRun::search(const design::DesignProblem &problem, const std::string &hash) {
    LcmEvaluator evaluator(problem, context_.router,
                           {request_.request_id, hash, request_.heuristic, context_.client},
                           cancelled_, context_.grace_s);
    {
        std::lock_guard lock(mutex_);
        evaluator_ = &evaluator;
    }
    planning::PlannerOptions planner;
    planner.heuristic = wire::heuristic_kind(request_.heuristic);
    // The coordinator's own planning (--prune relevant, the explanation's plans, why a task
    // is unsolvable) is bounded as a planner's job is: a spec cannot grow the coordinator.
    planner.limits.memory_limit_bytes = COORDINATOR_PLAN_BYTES;
    design::PlanCache local_planner(planner);
    auto on_progress = [&](const design::SearchProgress &p) {
        std::lock_guard lock(mutex_);
        progress_.done = p.done;
        progress_.total = p.total;
        progress_.best_objective = p.best_objective;
        progress_.planner_runs = p.planner_runs;
        progress_.cache_hits = p.cache_hits;
    };
    // Evaluations do not depend on D or the weights: those an earlier request with the same
    // models and modifications made are re-weighted, not re-planned.
    std::shared_ptr<design::EvaluationStore> store =
        context_.stores ? context_.stores->store_for(problem, request_.heuristic) : nullptr;
    std::optional<design::StoredEvaluator> stored;
    if (store)
        stored.emplace(problem, evaluator, *store);
    if (store && store->durable()) // each answer on disk before the search uses it
        evaluator.on_answer([&](const design::Configuration &c, const design::JobAnswer &a) {
            if (a.job.kind == design::JobKind::ROBOT_BOUND && a.robot_bound)
                stored->keep_robot_bound(c, a.job.task,
                                         {*a.robot_bound, a.ie_floor, a.explanation_floor});
            else if (a.job.kind == design::JobKind::EXPLICABILITY)
                stored->keep_task(c, a.job.task, a.explicability);
        });
    design::Evaluator &inner = stored ? static_cast<design::Evaluator &>(*stored) : evaluator;
    design::EvaluationLog searched(problem, inner); // kept for the explanation's break-even
    design::DesignRun run;
    try {
        run = design::run_design(problem, searched, &local_planner, settings(), on_progress);
    } catch (...) {
        std::lock_guard lock(mutex_);
        evaluator_ = nullptr;
        throw;
    }
    wire::TransportCounters transport;
    {
        std::lock_guard lock(mutex_);
        evaluator_ = nullptr;
    }
    PoolCounters pool = evaluator.transport();
    transport.jobs_sent = pool.jobs_sent;
    transport.jobs_resent = pool.jobs_resent;
    transport.duplicates_ignored = pool.duplicates;
    transport.planners_used = static_cast<int>(pool.answered_by.size());
    transport.transport_seconds = evaluator.transport_seconds();
    transport.job_seconds = evaluator.job_seconds();
    transport.stored_answers = stored ? stored->stored_answers() : 0;
    if (context_.stores)
        context_.stores->trim();
    finish(wire::result_message(problem, run, transport));
}

design::RunSettings RequestRun::settings() const {
    design::RunSettings settings;
    settings.time_limit_s = request_.time_limit_s;
    settings.max_time_limit_s = context_.max_time_limit_s;
    settings.max_design_size = request_.max_design_size;
    settings.method = request_.search == design_request_t::SEARCH_EXHAUSTIVE
                          ? design::SearchMethod::EXHAUSTIVE
                          : design::SearchMethod::WITNESS;
    settings.prune_relevant = request_.prune == design_request_t::PRUNE_RELEVANT;
    settings.ranking = request_.ranking;
    settings.ranking_all = request_.ranking_all == 1;
    settings.batch_size = std::max(8, 4 * context_.router.pool().capacity());
    settings.stop = &cancelled_;           // a cancelled request stops as at its deadline
    settings.explain_when_stopped = false; // and nobody waits for its explanation
    return settings;
}

void RequestRun::set_state(std::int8_t state) {
    std::lock_guard lock(mutex_);
    progress_.state = state;
}

void RequestRun::finish(envdesign::design_result_t result) {
    result.request_id = request_.request_id;
    result.client = request_.sender;
    auto &log = context_.bus.log();
    if (result.status == "error")
        log.warn("request {} | failed (exit {}): {}", name_, result.exit_code, result.error);
    else
        log.info("request {} | {}: objective {} after {} configuration(s) in {:.3f} s", name_,
                 result.status, result.best.objective, result.counters.configurations_evaluated,
                 result.counters.seconds);
    {
        std::lock_guard lock(mutex_);
        result_ = std::move(result);
        progress_.state = design_progress_t::STATE_DONE;
    }
    finished_ = true;
}

} // namespace envdesign::cluster
