#pragma once
// The one evaluation of a task under a configuration, for the spec's robot behaviour
// (behaviour.h): every evaluator calls it.
//
//   TaskExplicability t = evaluate_task_behaviour(models, weights, planner, deadline);

#include "design/design_problem.h"
#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/search/deadline.h"

namespace envdesign::design {

// evaluate_explicability (EXPLICABLE), evaluate_cost_optimal (COST_OPTIMAL, and its best
// case), or both options of evaluate_explaining (EXPLAINING). LIMIT (an empty evaluation) if
// the deadline passed. Throws pddl::ParseError if a model cannot be grounded.
TaskExplicability evaluate_task_behaviour(const ModelPair &models, const ObjectiveWeights &weights,
                                          PlanCache &planner, const Deadline &deadline);

} // namespace envdesign::design
