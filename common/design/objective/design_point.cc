#include "design/objective/design_point.h"

#include "design/behaviour/behaviour.h"

#include <cmath>

namespace envdesign::design {

DesignPoint design_point(const DesignProblem &problem, const Configuration &configuration,
                         const std::vector<TaskExplicability> &tasks) {
    DesignPoint point{configuration, design_cost(problem, configuration), 0, 0, {}, {}};
    if (behaviour_of(problem.weights.behaviour).may_explain) {
        for (std::size_t i = 0; i < tasks.size() && i < problem.tasks.size(); ++i) {
            TaskExplicability t = tasks[i];
            t.plan.clear();
            t.human_plan.reset();
            if (t.explanation)
                t.explanation->robot_plan.clear();
            point.probabilities.push_back(problem.tasks[i].probability);
            point.explaining_tasks.push_back(std::move(t));
        }
        // Not a fixed point under other weights: the expectations are "not known" (NaN).
        point.expected_ie = point.expected_robot_cost = std::nan("");
        return point;
    }
    for (std::size_t i = 0; i < tasks.size() && i < problem.tasks.size(); ++i) {
        double p = problem.tasks[i].probability;
        if (p <= 0)
            continue;
        if (tasks[i].status != ExplicabilityStatus::SOLVED) {
            point.expected_ie = point.expected_robot_cost = INF;
            return point;
        }
        // Summed in task order, as objective_of() does, so that both agree exactly.
        point.expected_ie += p * tasks[i].ie;
        point.expected_robot_cost += p * tasks[i].robot_cost;
    }
    return point;
}

Objective objective_at(const ObjectiveWeights &w, const DesignPoint &point) {
    if (!point.explaining_tasks.empty()) // each task's option chosen again under `w`
        return objective_of(w, point.design_cost, point.probabilities, point.explaining_tasks);
    Objective out;
    out.terms.design_cost = point.design_cost;
    if (point.expected_ie == INF)
        return out; // infinite, whatever the weights
    out.terms.inexplicability = point.expected_ie * discounted_horizon(w);
    out.terms.robot_cost = w.horizon * point.expected_robot_cost;
    out.value = objective_value(w, out.terms);
    return out;
}

RankedDesign ranked_at(const ObjectiveWeights &weights, const DesignPoint &point) {
    return {objective_at(weights, point).value, point.design_cost, point.configuration};
}

} // namespace envdesign::design
