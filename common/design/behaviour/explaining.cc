#include "design/behaviour/explaining.h"

#include "design/behaviour/explicability.h"
#include "design/objective/objective.h"
#include "design/reconciliation/minimal_explanation.h"

#include <cmath>

namespace envdesign::design {
namespace {

// The explanation when the most explicable plan is itself optimal for both models: pi is
// then an optimal plan of P_R that needs no explanation (E = {}), so no search is needed.
std::optional<TaskExplanation> nothing_to_tell(const TaskExplicability &t, double robot_optimal,
                                               Distance distance) {
    if (t.status != ExplicabilityStatus::SOLVED || t.ie != least_ie(distance) ||
        t.robot_cost != robot_optimal)
        return std::nullopt;
    return TaskExplanation{true, robot_optimal, t.plan, {}};
}

} // namespace

PlanChoice robot_plan_choice(const Behaviour &behaviour) {
    return behaviour.may_explain ? PlanChoice::PLANNERS : PlanChoice::ANY_OPTIMAL;
}

TaskExplicability evaluate_explaining(const ModelPair &models, const ObjectiveWeights &w,
                                      PlanCache &planner, const Deadline &deadline) {
    TaskExplicability t = evaluate_explicability(models, w.distance, planner, deadline);
    if (t.status == ExplicabilityStatus::LIMIT)
        return t;
    PlanOutcome robot = solve_model(models.robot_domain, models.robot_problem, planner, deadline,
                                    PlanChoice::PLANNERS);
    if (robot.status == PlanStatus::LIMIT)
        return TaskExplicability{};
    if (robot.status == PlanStatus::UNSOLVABLE) {
        t.explanation = TaskExplanation{};
        return t;
    }
    double robot_optimal = static_cast<double>(robot.cost);
    if ((t.explanation = nothing_to_tell(t, robot_optimal, w.distance)))
        return t;
    ExplanationSearch search = minimal_explanation(models, robot.plan, planner, deadline);
    if (search.status == ExplanationStatus::LIMIT)
        return TaskExplicability{};
    TaskExplanation x{
        search.status == ExplanationStatus::FOUND, robot_optimal, std::move(robot.plan), {}};
    for (int i : search.chosen)
        x.differences.push_back(search.differences[i].text);
    t.explanation = std::move(x);
    return t;
}

} // namespace envdesign::design
