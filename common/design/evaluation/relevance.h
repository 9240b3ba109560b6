#pragma once
// The paper's pruning (--prune relevant): from a configuration, the search only adds the
// modifications that touch an action of an optimal robot plan (P_R) or of an expected human
// plan (an optimal plan of P_H) of some task *in that configuration* ("we restricted the set
// of applicable designs at each node to the ones that affect the current expected human
// plan"). Not exact: each model has one optimal plan computed, while the human may expect
// any of several, and a modification touching none of them can still matter; the search
// then reports "best_found".
//
// An edit touches the plans when
//   - it changes the precondition or effect of a schema one of the plans uses, or removes
//     that schema or one of the plans' ground actions;
//   - it adds or removes an init atom that is a precondition or effect of a plan step;
//   - it changes a goal (every plan is about the goal).
// add_predicate alone touches nothing.

#include "design/design_problem.h"
#include "design/evaluation/plan_cache.h"
#include "design/model/configuration.h"
#include "design/search/deadline.h"

#include <vector>

namespace envdesign::design {

// The indices (ascending) of the modifications relevant in `configuration` (those already
// in it included). Plans through `planner`, so the runs count in its statistics; the human
// plans are usually cache hits, as evaluating the configuration solved P_H already.
std::vector<int> relevant_modifications(const DesignProblem &problem,
                                        const Configuration &configuration, PlanCache &planner,
                                        const Deadline &deadline);

} // namespace envdesign::design
