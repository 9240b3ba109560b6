#pragma once
// One task's evaluation when the robot is not an explicable planner (SPEC.md, issue 14):
//   COST_OPTIMAL:           the robot runs some cost-optimal plan of P_R, we do not know
//                           which; IE = the largest IE over all of them (+inf if one is not
//                           a valid plan of P_H);
//   COST_OPTIMAL_BEST_CASE: the least IE over them (+inf if none is valid for P_H).
// robot_cost is c_R*, plan a worst (best) optimal plan, human_plan an optimal plan of P_H,
// optimal_actions every action of the optimal-plan graph. Status INEXPLICABLE when P_R or
// P_H has no plan (IE and robot cost +inf, as for EXPLICABLE: restricting modifications keep
// it so); SOLVED otherwise, with IE possibly +inf (a modification of the robot's model may
// remove the offending plans); LIMIT when the deadline or the planner's memory limit
// (PlannerOptions::limits) was reached.
//
// Example:
//   TaskExplicability e = evaluate_cost_optimal(models, weights, planner, deadline);

#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/search/deadline.h"

#include <string>

namespace envdesign::design {

// `weights.behaviour` must be COST_OPTIMAL or COST_OPTIMAL_BEST_CASE. The optimal costs
// come through `planner` (cached); the graph and the product are built here.
// Throws pddl::ParseError if a model cannot be grounded.
TaskExplicability evaluate_cost_optimal(const ModelPair &models, const ObjectiveWeights &weights,
                                        PlanCache &planner, const Deadline &deadline);

} // namespace envdesign::design
