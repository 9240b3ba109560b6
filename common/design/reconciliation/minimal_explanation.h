#pragma once
// Minimal explanations (model reconciliation, Chakraborti et al., IJCAI 2017): the smallest
// set E of model differences (model_differences.h) such that the robot's plan pi_R is valid
// and optimal in the human's model updated by E:
//   pi_R valid in P_H + E  and  c_{H+E}(pi_R) = c*_{H+E}.
// Costs are the human's (the observers judge the plan by their model). pi_R is the planner's
// optimal plan of P_R (deterministic: the plan cache's canonical task). The choice matters:
// another optimal plan of P_R may need a smaller or a larger explanation; we explain the
// plan the robot will run.
//
// The search is the paper's, best first over subsets by size, with the planner as the check:
// subsets of size 0, 1, 2, ... in lexicographic order; the first that passes is minimal by
// count. Each subset is first checked for the validity of pi_R by the independent plan
// validator (no planner), then c*_{H+E} is found by the planner (cached by lifted model).
// Pruning that keeps minimality: differences about predicates no precondition or goal reads
// are not candidates (model_differences.h: they change no plan). Nothing else is skipped, so
// the count of subsets tried is sum_{k<=|E|} C(n, k); the deadline bounds it (LIMIT).
// When every difference only removes plans of P_H (explanation_hitting.h), an exact implicit
// hitting-set search replaces the enumeration: one planner call per cheaper human plan met,
// not one per subset (the IPC-Grid problems have 36 differences and explanations of 6 or more).

#include "design/evaluation/plan_cache.h"
#include "design/model/configuration.h"
#include "design/reconciliation/explanation_search.h"
#include "design/reconciliation/model_differences.h"
#include "design/search/deadline.h"

#include <optional>
#include <vector>

namespace envdesign::design {

// Whether pi_R is valid and optimal in the human's model of `told` (the planner decides the
// optimum); nullopt when the deadline passed first.
std::optional<bool> plan_optimal_for_human(const ModelPair &told,
                                           const std::vector<std::string> &robot_plan,
                                           PlanCache &planner, const Deadline &deadline);

// A minimal explanation of `robot_plan` (an optimal plan of models' P_R).
ExplanationSearch minimal_explanation(const ModelPair &models,
                                      const std::vector<std::string> &robot_plan,
                                      PlanCache &planner, const Deadline &deadline);

} // namespace envdesign::design
