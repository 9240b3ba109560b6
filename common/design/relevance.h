#pragma once
// The paper's pruning (--prune relevant): keep only the modifications that touch an action
// of an optimal robot plan (P_R) or of an expected human plan (an optimal plan of P_H) of
// some task in the unmodified environment. Not exact: a modification elsewhere can still
// matter (a barrier that makes a detour the human's new expectation), which is why the
// search reports "best_found" when this drops anything.
//
// An edit touches the plans when
//   - it changes the precondition or effect of a schema one of the plans uses, or removes
//     that schema or one of the plans' ground actions;
//   - it adds or removes an init atom that is a precondition or effect of a plan step;
//   - it changes a goal (every plan is about the goal).
// add_predicate alone touches nothing.

#include "design/deadline.h"
#include "design/design_problem.h"
#include "design/plan_cache.h"

#include <vector>

namespace envdesign::design {

// The indices (ascending) of the relevant modifications. Plans through `planner`, so the
// runs count in its statistics.
std::vector<int> relevant_modifications(const DesignProblem &problem, PlanCache &planner,
                                        const Deadline &deadline);

}  // namespace envdesign::design
