#pragma once
// The in-process Evaluator: `workers` threads evaluate (configuration, task) pairs, sharing
// one PlanCache, while the calling thread dispatches pairs (at most one per worker in
// flight, so that `abandon` sees the latest results) and collects the answers.

#include "design/design_problem.h"
#include "design/evaluator.h"
#include "design/plan_cache.h"

namespace envdesign::design {

class LocalEvaluator : public Evaluator {
public:
    // `problem` must outlive the evaluator.
    LocalEvaluator(const DesignProblem &problem, int workers,
                   planning::PlannerOptions options = {});

    void evaluate(const std::vector<Configuration> &batch, const Deadline &deadline,
                  const EvaluationCallbacks &callbacks) override;
    EvaluatorCounters counters() const override;

    // The evaluation of one pair, as a worker does it (also used for --prune relevant).
    TaskExplicability evaluate_task(const Configuration &configuration, int task,
                                    const Deadline &deadline);
    PlanCache &planner() { return cache_; }

private:
    const DesignProblem &problem_;
    int workers_;
    PlanCache cache_;
    long long task_evaluations_ = 0;
};

}  // namespace envdesign::design
