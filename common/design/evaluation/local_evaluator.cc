#include "design/evaluation/local_evaluator.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/evaluate_task.h"
#include "design/behaviour/explaining.h"
#include "design/behaviour/explicability.h"
#include "design/evaluation/dispatcher.h"
#include "design/reconciliation/explanation_floor.h"
#include "design/search/witness.h"
#include "validate/plan_validator.h"

#include "concurrency/blocking_queue.h"

#include <cmath>
#include <exception>
#include <thread>

namespace envdesign::design {

Evaluator::~Evaluator() = default;

ConfigurationEvaluation unevaluated(Configuration configuration) {
    return {std::move(configuration), EvaluationStatus::LIMIT, {}, {}, {}};
}

namespace {

struct Answer {
    JobAnswer answer;
    std::exception_ptr error;
};

// Jobs go to the workers, answers come back to the dispatcher.
struct Channel {
    concurrency::BlockingQueue<Job> jobs;       // closed once no job is in flight
    concurrency::BlockingQueue<Answer> answers; // never closed: each job sends one
};

} // namespace

LocalEvaluator::LocalEvaluator(const DesignProblem &problem, int workers,
                               planning::PlannerOptions options)
    : problem_(problem), workers_(std::max(1, workers)), cache_(std::move(options)),
      ie_floors_(ie_floors_hold(problem)), robot_bounds_(asks_robot_bounds(problem)),
      human_optima_(TouchIndex(problem).human_restricting()) {}

TaskExplicability LocalEvaluator::evaluate_task(const Configuration &configuration, int task,
                                                const Deadline &deadline) {
    ModelPair models = configured_models(problem_, configuration, task);
    return evaluate_task_behaviour(models, problem_.weights, cache_, deadline);
}

std::optional<double> LocalEvaluator::robot_cost_bound(const Configuration &configuration, int task,
                                                       const Deadline &deadline) {
    ModelPair models = configured_models(problem_, configuration, task);
    // The plan the evaluation of the explaining robot asks for: then that is a cache hit.
    PlanOutcome robot = solve_model(models.robot_domain, models.robot_problem, cache_, deadline,
                                    robot_plan_choice(behaviour_of(problem_.weights.behaviour)));
    if (robot.status == PlanStatus::SOLVED)
        return static_cast<double>(robot.cost);
    if (robot.status == PlanStatus::UNSOLVABLE)
        return INF;
    return std::nullopt;
}

void LocalEvaluator::floors(const Configuration &configuration, int task, const Deadline &deadline,
                            JobAnswer &answer) {
    const std::optional<double> &robot_bound = answer.robot_bound;
    if (!ie_floors_ || !robot_bound || !std::isfinite(*robot_bound))
        return;
    const ObjectiveWeights &w = problem_.weights;
    std::vector<std::optional<double>> human_optimum(problem_.tasks.size());
    {
        std::lock_guard lock(human_optima_mutex_);
        human_optima_.inherit(configuration, human_optimum);
    }
    if (human_optimum[task] && *human_optimum[task] >= *robot_bound) { // as solving would say
        answer.ie_floor = least_ie(w.distance);
        return;
    }
    ModelPair models = configured_models(problem_, configuration, task);
    PlanOutcome human =
        human_optimal_plan(configuration, task, models, human_optimum[task], deadline);
    if (human.status != PlanStatus::SOLVED)
        return;
    answer.ie_floor = ie_floor(*robot_bound, static_cast<double>(human.cost), w.distance);
    // Above the least IE, the human's plan costs people less than pi_R (ie_floor's argument).
    if (behaviour_of(w.behaviour).may_explain && *answer.ie_floor > least_ie(w.distance))
        answer.explanation_floor = explanation_floor(models, human.plan, *robot_bound);
}

// c_H* of the task under `configuration`, with an optimal plan. `inherited` is the greatest
// c_H* of its subsets one human-restricting modification smaller (it never drops): where one
// of their optimal plans costing that much is valid here, it is optimal here too, and no A*
// runs. Remembers what it found for the configurations one larger.
PlanOutcome LocalEvaluator::human_optimal_plan(const Configuration &configuration, int task,
                                               const ModelPair &models,
                                               std::optional<double> inherited,
                                               const Deadline &deadline) {
    std::vector<KeptPlan> candidates;
    if (inherited) {
        std::lock_guard lock(human_optima_mutex_);
        for (const Configuration &parent : human_optima_.parents(configuration)) {
            auto it = human_plans_.find(parent);
            if (it != human_plans_.end() && it->second[task])
                candidates.push_back(it->second[task]);
        }
    }
    PlanOutcome human;
    for (const KeptPlan &plan : candidates) {
        auto v = validate::validate_plan(models.human_domain, models.human_problem, *plan);
        if (v.valid && static_cast<double>(v.cost) == *inherited) {
            human = {PlanStatus::SOLVED, v.cost, 0, *plan};
            break;
        }
    }
    if (human.status != PlanStatus::SOLVED)
        human = solve_model(models.human_domain, models.human_problem, cache_, deadline);
    if (human.status != PlanStatus::SOLVED)
        return human;
    std::vector<std::optional<double>> optimum(problem_.tasks.size());
    optimum[task] = static_cast<double>(human.cost);
    std::lock_guard lock(human_optima_mutex_);
    if (human_optima_.size() < kHumanOptimaKept) // a planner service keeps its evaluators
        human_optima_.remember(configuration, optimum);
    auto kept = human_plans_.find(configuration);
    if (kept == human_plans_.end() && human_plans_.size() < kHumanPlansKept)
        kept =
            human_plans_.emplace(configuration, std::vector<KeptPlan>(problem_.tasks.size())).first;
    if (kept != human_plans_.end() && !kept->second[task])
        kept->second[task] = std::make_shared<const std::vector<std::string>>(human.plan);
    return human;
}

JobAnswer LocalEvaluator::answer(const Configuration &configuration, const Job &job,
                                 const Deadline &deadline) {
    JobAnswer answer{job, std::nullopt, std::nullopt, {}};
    if (job.kind == JobKind::ROBOT_BOUND) {
        answer.robot_bound =
            job.robot_bound ? job.robot_bound : robot_cost_bound(configuration, job.task, deadline);
        floors(configuration, job.task, deadline, answer);
    } else
        answer.explicability = evaluate_task(configuration, job.task, deadline);
    return answer;
}

void LocalEvaluator::evaluate(const std::vector<ConfigurationEvaluation> &batch,
                              const Deadline &deadline, const EvaluationCallbacks &callbacks) {
    Dispatcher dispatcher(batch, static_cast<int>(problem_.tasks.size()), robot_bounds_, ie_floors_,
                          callbacks, behaviour_of(problem_.weights.behaviour).may_explain);
    Channel channel;
    std::vector<std::thread> threads;
    for (int i = 0; i < workers_; ++i) {
        threads.emplace_back([&] {
            while (auto job = channel.jobs.pop()) {
                Answer a{{*job, std::nullopt, std::nullopt, {}}, nullptr};
                try {
                    a.answer = answer(batch[job->configuration].configuration, *job, deadline);
                } catch (...) {
                    a.error = std::current_exception();
                }
                channel.answers.push(std::move(a));
            }
        });
    }
    std::exception_ptr error;
    int in_flight = 0;
    while (true) {
        while (in_flight < workers_ && !error && !deadline.expired()) {
            auto job = dispatcher.next_job();
            if (!job)
                break;
            channel.jobs.push(*job);
            ++in_flight;
        }
        if (in_flight == 0)
            break;
        Answer a = *channel.answers.pop();
        --in_flight;
        if (a.answer.job.kind == JobKind::EXPLICABILITY)
            ++task_evaluations_;
        if (a.error && !error)
            error = a.error;
        if (!a.error)
            dispatcher.receive(std::move(a.answer));
    }
    channel.jobs.close();
    for (auto &t : threads)
        t.join();
    if (error)
        std::rethrow_exception(error);
    dispatcher.finish_rest();
}

EvaluatorCounters LocalEvaluator::counters() const {
    CacheCounters c = cache_.counters();
    return {task_evaluations_, c.planner_runs, c.cache_hits, c.groundings_skipped,
            c.planner_seconds};
}

} // namespace envdesign::design
