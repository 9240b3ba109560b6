#pragma once
// A floor on the size of any explanation, from one plan of the human's model cheaper than the
// robot's, without the planner: the design search's bound for a task not evaluated yet
// (docs/behaviours-explaining.md, "Explanation floors").
//
// Let pi' be a plan of P_H whose human cost is below a lower bound on c_H(pi_R). An explanation
// E makes pi_R optimal in P_H + E, so pi' must be invalid there, or cost no less (action costs
// are not differences, so it costs the same if valid). Only the differences pi' reads can
// change it (plan_reads.h). So |E| is at least the least k such that telling some k of them
// stops pi' from being cheaper: found by trying their subsets by size, with the validator.

#include "design/model/configuration.h"

#include <string>
#include <vector>

namespace envdesign::design {

// The floor as above for `human_plan` (a plan of models' P_H) and `robot_cost_floor` (at most
// the human cost of pi_R): 0 when the plan is not cheaper than that; |relevant| + 1 when no
// subset stops it (no explanation exists). Tries at most `max_subsets` subsets; stopped within
// size k, it answers k (every smaller subset was tried).
int explanation_floor(const ModelPair &models, const std::vector<std::string> &human_plan,
                      double robot_cost_floor, long long max_subsets = 256);

} // namespace envdesign::design
