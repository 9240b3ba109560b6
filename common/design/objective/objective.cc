#include "design/objective/objective.h"

#include "design/behaviour/behaviour.h"
#include "design/objective/formula.h"

#include <algorithm>
#include <cmath>

namespace envdesign::design {
namespace {

// alpha * H * ie + extra + kappa * T * cost, infinite (not NaN) when any part is.
double contribution(const ObjectiveWeights &w, double ie, double extra, double cost) {
    if (std::isinf(ie) || std::isinf(cost))
        return INF;
    double value = w.alpha * discounted_horizon(w) * ie + extra + w.kappa * w.horizon * cost;
    return std::isnan(value) ? INF : value;
}

// The least a task not evaluated yet can cost, from its IE floor: acting at IE >= floor, or
// (a robot that may explain, floor above the least IE) explaining at least `told` differences,
// and at least one.
BehaviourChoice floor_choice(const ObjectiveWeights &w, double floor, double robot_bound,
                             int told) {
    double least = least_ie(w.distance);
    BehaviourChoice act{true, false, std::max(floor, least), robot_bound, 0};
    if (!behaviour_of(w.behaviour).may_explain || act.ie <= least)
        return act;
    double explained = w.explanation_cost * std::max(1, told);
    BehaviourChoice explain{true, true, least, robot_bound, explained};
    double act_value = contribution(w, act.ie, 0, robot_bound);
    double explain_value = contribution(w, least, discounted_horizon(w) * explained, robot_bound);
    return explain_value < act_value ? explain : act;
}

} // namespace

double objective_value(const ObjectiveWeights &w, const ObjectiveTerms &t) {
    return formula::weighted_sum(w.alpha, w.beta, w.kappa, t.inexplicability, t.design_cost,
                                 t.robot_cost, t.explanation);
}

double discounted_horizon(const ObjectiveWeights &weights) {
    return formula::discounted_horizon(weights.gamma, weights.horizon);
}

Objective objective_of(const DesignProblem &problem, double design_cost,
                       const std::vector<TaskExplicability> &tasks) {
    std::vector<double> probabilities;
    for (std::size_t i = 0; i < tasks.size(); ++i)
        probabilities.push_back(problem.tasks[i].probability);
    return objective_of(problem.weights, design_cost, probabilities, tasks);
}

Objective objective_of(const ObjectiveWeights &w, double design_cost,
                       const std::vector<double> &probabilities,
                       const std::vector<TaskExplicability> &tasks) {
    Objective out;
    out.terms.design_cost = design_cost;
    double expected_ie = 0, expected_cost = 0, expected_explanation = 0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        double p = probabilities[i];
        if (p <= 0)
            continue;
        BehaviourChoice c = choose_behaviour(w, tasks[i]);
        if (!c.finite)
            return out; // infinite
        expected_ie += p * c.ie;
        expected_cost += p * c.robot_cost;
        expected_explanation += p * c.explanation;
    }
    out.terms.inexplicability = expected_ie * discounted_horizon(w);
    out.terms.robot_cost = w.horizon * expected_cost;
    out.terms.explanation = expected_explanation * discounted_horizon(w);
    out.value = objective_value(w, out.terms);
    return out;
}

double objective_lower_bound(const DesignProblem &problem, double design_cost,
                             const std::vector<const TaskExplicability *> &known,
                             const std::vector<std::optional<double>> &robot_cost_bounds,
                             const std::vector<std::optional<double>> &ie_floors,
                             const std::vector<std::optional<int>> &explanation_floors) {
    const ObjectiveWeights &w = problem.weights;
    double expected_ie = 0, expected_cost = 0, expected_explanation = 0;
    for (std::size_t i = 0; i < problem.tasks.size(); ++i) {
        double p = problem.tasks[i].probability;
        if (p <= 0)
            continue;
        const TaskExplicability *t = i < known.size() ? known[i] : nullptr;
        bool settled = t && t->status != ExplicabilityStatus::LIMIT;
        BehaviourChoice c = settled ? choose_behaviour(w, *t) : BehaviourChoice{};
        if (settled && !c.finite)
            return INF;
        double bound =
            i < robot_cost_bounds.size() && robot_cost_bounds[i] ? *robot_cost_bounds[i] : 0.0;
        if (!settled && std::isinf(bound))
            return INF;
        // An unknown task: robot cost at least c_R* (both options), and the cheaper of its
        // IE floor (the least IE without one) and, for a robot that may explain, telling its
        // explanation floor, or one difference (explicability.h: above the least IE, pi_R
        // needs one).
        if (!settled) {
            double floor = i < ie_floors.size() && ie_floors[i] ? *ie_floors[i] : 0;
            int told =
                i < explanation_floors.size() && explanation_floors[i] ? *explanation_floors[i] : 1;
            c = floor_choice(w, floor, bound, told);
        }
        expected_ie += p * c.ie;
        expected_cost += p * c.robot_cost;
        expected_explanation += p * c.explanation;
    }
    ObjectiveTerms terms{expected_ie * discounted_horizon(w), design_cost,
                         w.horizon * expected_cost, expected_explanation * discounted_horizon(w)};
    return objective_value(w, terms);
}

bool nearly_equal(double a, double b) {
    if (std::isinf(a) || std::isinf(b))
        return a == b;
    // A few ulps: enough for sums taken in different orders, too little to merge designs
    // whose objectives really differ (with IE near e^30 a 1e-9 tolerance merged gaps of 10^4).
    return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
}

bool clearly_greater(double a, double b) { return a > b && !nearly_equal(a, b); }

bool ranks_before(const RankedDesign &a, const RankedDesign &b) {
    if (!nearly_equal(a.objective, b.objective))
        return a.objective < b.objective;
    if (a.configuration.size() != b.configuration.size())
        return a.configuration.size() < b.configuration.size();
    if (!nearly_equal(a.design_cost, b.design_cost))
        return a.design_cost < b.design_cost;
    return a.configuration < b.configuration;
}

BehaviourChoice choose_behaviour(const ObjectiveWeights &w, const TaskExplicability &t) {
    BehaviourChoice act{t.status == ExplicabilityStatus::SOLVED, false, t.ie, t.robot_cost, 0};
    if (!behaviour_of(w.behaviour).may_explain || !t.explanation || !t.explanation->found)
        return act;
    const TaskExplanation &x = *t.explanation;
    double told = w.explanation_cost * static_cast<double>(x.differences.size());
    BehaviourChoice explain{true, true, least_ie(w.distance), x.robot_optimal_cost, told};
    double act_value = act.finite ? contribution(w, act.ie, 0, act.robot_cost) : INF;
    double explain_value =
        contribution(w, explain.ie, discounted_horizon(w) * told, explain.robot_cost);
    if (std::isinf(explain_value))
        return act;
    return clearly_greater(act_value, explain_value) ? explain : act;
}

} // namespace envdesign::design
