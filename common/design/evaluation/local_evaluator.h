#pragma once
// The in-process Evaluator: `workers` threads run the jobs of a Dispatcher (dispatcher.h),
// sharing one PlanCache, while the calling thread hands out jobs (at most one per worker in
// flight, so that `abandon` sees the latest answers) and collects the answers. Robot-cost
// bounds are asked for when the objective weighs the robot's cost (kappa > 0) or when they
// give IE floors: where people's costs are at least the robot's (human_costs_dominate), a
// ROBOT_BOUND job also solves the human's model and answers ie_floor (explicability.h), so a
// design whose robot must do what people think takes longer is abandoned without the
// compiled task or an explanation (the EXPLICABILITY job then finds c_H* in the plan cache).

#include "design/design_problem.h"
#include "design/evaluation/dispatcher.h"
#include "design/evaluation/evaluator.h"
#include "design/evaluation/plan_cache.h"
#include "design/search/rising_bounds.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace envdesign::design {

class LocalEvaluator : public Evaluator {
public:
    // `problem` must outlive the evaluator.
    LocalEvaluator(const DesignProblem &problem, int workers,
                   planning::PlannerOptions options = {});

    void evaluate(const std::vector<ConfigurationEvaluation> &batch, const Deadline &deadline,
                  const EvaluationCallbacks &callbacks) override;
    EvaluatorCounters counters() const override;

    // The evaluation of one pair, as a worker does it (also used for --prune relevant).
    TaskExplicability evaluate_task(const Configuration &configuration, int task,
                                    const Deadline &deadline);
    // The robot's optimal cost under `configuration` (INF: no plan; unset: out of time).
    std::optional<double> robot_cost_bound(const Configuration &configuration, int task,
                                           const Deadline &deadline);
    // ie_floor of the task under `configuration` given its robot bound, into `answer`
    // (and, for a robot that may explain, its explanation_floor); unset where no floor is
    // argued (see above) or out of time.
    void floors(const Configuration &configuration, int task, const Deadline &deadline,
                JobAnswer &answer);
    PlanCache &planner() { return cache_; }

    // The answer to one job, as a worker (or a planner service) computes it.
    JobAnswer answer(const Configuration &configuration, const Job &job, const Deadline &deadline);

private:
    const DesignProblem &problem_;
    int workers_;
    PlanCache cache_;
    bool ie_floors_; // before robot_bounds_, which reads it
    bool robot_bounds_;
    // c_H* of the configurations the floor jobs solved: a subset's c_H* bounds a configuration
    // one human-restricting modification larger (rising_bounds.h), and where it reaches the
    // robot bound the floor is the least IE without the human's A*.
    RisingBounds human_optima_;
    static constexpr std::size_t kHumanOptimaKept = 1 << 16; // configurations
    // The optimal plans behind them, per task: one still valid one rising modification larger
    // is optimal there too (it costs the bound), so that floor job needs no A*.
    using KeptPlan = std::shared_ptr<const std::vector<std::string>>;
    std::map<Configuration, std::vector<KeptPlan>> human_plans_;
    static constexpr std::size_t kHumanPlansKept = 1 << 12; // configurations
    std::mutex human_optima_mutex_;
    PlanOutcome human_optimal_plan(const Configuration &configuration, int task,
                                   const ModelPair &models, std::optional<double> inherited,
                                   const Deadline &deadline);
    long long task_evaluations_ = 0;
};

} // namespace envdesign::design
