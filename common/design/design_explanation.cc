#include "design/design_explanation.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/explaining.h"
#include "design/behaviour/explicability.h"

#include <algorithm>
#include <map>

namespace envdesign::design {
namespace {

Configuration without(const Configuration &configuration, int modification) {
    Configuration out;
    for (int m : configuration)
        if (m != modification)
            out.push_back(m);
    return out;
}

// Evaluates through `log` every configuration of `wanted` it does not know (and {} when
// its tasks are wanted), returning the tasks of each design evaluated here.
std::map<Configuration, std::vector<TaskExplicability>>
evaluate_missing(EvaluationLog &log, const std::vector<Configuration> &wanted, bool need_baseline,
                 const Deadline &deadline) {
    std::vector<ConfigurationEvaluation> batch;
    for (const auto &c : wanted) {
        bool needed = !log.find(c) || (c.empty() && need_baseline);
        bool queued = std::any_of(batch.begin(), batch.end(),
                                  [&](const auto &e) { return e.configuration == c; });
        if (needed && !queued)
            batch.push_back(unevaluated(c));
    }
    std::map<Configuration, std::vector<TaskExplicability>> out;
    if (batch.empty() || deadline.expired())
        return out;
    EvaluationCallbacks callbacks;
    callbacks.abandon = [](const ConfigurationEvaluation &) { return false; };
    callbacks.done = [&](ConfigurationEvaluation e) {
        if (e.status != EvaluationStatus::COMPLETE)
            return;
        std::vector<TaskExplicability> tasks;
        for (auto &t : e.tasks)
            tasks.push_back(t.value_or(TaskExplicability{}));
        out[e.configuration] = std::move(tasks);
    };
    log.evaluate(batch, deadline, callbacks);
    return out;
}

void add_plans(const DesignProblem &problem, const Configuration &chosen, int task,
               PlanCache &planner, const Deadline &deadline, TaskComparison &out) {
    ModelPair models = configured_models(problem, chosen, task);
    PlanOutcome robot = solve_model(models.robot_domain, models.robot_problem, planner, deadline,
                                    robot_plan_choice(behaviour_of(problem.weights.behaviour)));
    if (robot.status == PlanStatus::SOLVED) {
        out.robot_plan = robot.plan;
        out.robot_optimal_cost = static_cast<double>(robot.cost);
    } else if (robot.status == PlanStatus::UNSOLVABLE) {
        out.robot_optimal_cost = INF;
    }
    if (out.expected_plan)
        return;
    PlanOutcome human = solve_model(models.human_domain, models.human_problem, planner, deadline);
    if (human.status == PlanStatus::SOLVED)
        out.expected_plan = human.plan;
}

} // namespace

DesignExplanation explain_design(const DesignProblem &problem, const DesignResult &result,
                                 EvaluationLog &log, PlanCache *planner, const Deadline &deadline) {
    const EvaluatedDesign &best = *result.best;
    const Configuration &chosen = best.ranked.configuration;
    DesignExplanation out;
    out.weights = problem.weights;
    out.discounted_horizon = discounted_horizon(problem.weights);
    out.least_ie = least_ie(problem.weights.distance);
    out.least_inexplicability = out.least_ie * out.discounted_horizon;
    out.chosen = design_point(problem, chosen, best.tasks);
    log.keep(out.chosen);
    if (result.baseline)
        log.keep(design_point(problem, {}, result.baseline->tasks));

    std::vector<Configuration> wanted{Configuration{}};
    for (int m : chosen)
        wanted.push_back(without(chosen, m));
    for (const auto &r : result.ranking)
        wanted.push_back(r.configuration);
    auto fresh = evaluate_missing(log, wanted, !result.baseline, deadline);

    const std::vector<TaskExplicability> *baseline =
        result.baseline ? &result.baseline->tasks : nullptr;
    if (!baseline && fresh.count({}))
        baseline = &fresh.at({});
    for (std::size_t i = 0; i < problem.tasks.size(); ++i) {
        TaskComparison t;
        t.chosen = best.tasks[i];
        if (baseline)
            t.baseline = (*baseline)[i];
        t.expected_plan = t.chosen.human_plan;
        if (planner)
            add_plans(problem, chosen, static_cast<int>(i), *planner, deadline, t);
        out.tasks.push_back(std::move(t));
    }
    for (int m : chosen)
        out.marginal.push_back({m, log.find(without(chosen, m))});
    if (result.ranking.empty())
        out.ranking.push_back(out.chosen);
    for (const auto &r : result.ranking)
        if (auto point = log.find(r.configuration))
            out.ranking.push_back(*point);
    // EXPLAINING: each task's choice moves with T and alpha, so the crossings of break_even.h
    // (linear in alpha and f_T) do not hold; none are computed (designs_compared 0).
    if (!behaviour_of(problem.weights.behaviour).may_explain)
        out.break_even = break_even(problem.weights, out.chosen, log.points());
    return out;
}

} // namespace envdesign::design
