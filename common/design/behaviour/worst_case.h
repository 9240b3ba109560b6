#pragma once
// How the robot's cost-optimal plans look to the observers (issue 14): the human cost
// c_H(pi) of the worst (COST_OPTIMAL) or the best (COST_OPTIMAL_BEST_CASE) cost-optimal plan
// pi of P_R, without enumerating plans.
//
// The human model runs alongside the optimal-plan graph (optimal_plan_graph.h): a product
// whose nodes pair a robot node with the human model's state after the same actions. An
// action the human model does not have, or whose human precondition fails, leads to "not
// valid for the human"; a plan ending where the human goal does not hold is not valid either.
//   - worst: +inf if any optimal robot plan is not valid for the human; else the longest
//     human cost of a path from the start to an end (a robot goal node) of the product;
//   - best: the shortest human cost of a path to an end where the human goal holds, +inf
//     if there is none.
//
// Zero-cost robot actions and cycles. With zero-cost robot actions the optimal-plan graph can
// have cycles, so P_R has infinitely many optimal plans (go round the cycle k times, for every
// k). If such a cycle costs the human something, the human costs of those plans have no
// bound: the worst case is +inf (the supremum over the optimal plans, as the definition
// says; the robot's planner is free to choose any of them). Restricting the worst case to
// simple paths instead would be the longest simple path problem (NP-hard), and would name
// a number that no definition of "the robot's plans" gives. Cycles of zero human cost
// change nothing and are contracted (strongly connected components). The best case never
// goes round a cycle (human costs are >= 0).
//
// Example:
//   HumanCost worst = human_cost_of_optimal_plans(graph, robot, human, Case::WORST, limits);

#include "design/behaviour/optimal_plan_graph.h"
#include "ground/ground_task.h"

#include <string>
#include <vector>

namespace envdesign::design {

enum class Case { WORST, BEST };

struct HumanCost {
    enum class Status { SOLVED, LIMIT };
    Status status = Status::LIMIT;
    // c_H(pi); +inf when the worst plan is not valid for the human or the human cost of the
    // optimal plans is unbounded (WORST), or no optimal plan is valid for the human (BEST).
    double cost = 0;
    // A plan of P_R (robot operator names) at that value: the worst/best one; for +inf, one
    // that is not valid for the human (goes round the costly cycle once when unbounded);
    // empty for BEST at +inf.
    std::vector<std::string> plan;
    std::size_t product_nodes = 0; // explored
};

// `robot`: the task the graph was built on; `human`: the human's model of the same task
// (ground without relevance pruning, so every action sequence of the model can be followed).
// Operators are matched by name. LIMIT when `limits` cut it short.
HumanCost human_cost_of_optimal_plans(const OptimalPlanGraph &graph,
                                      const ground::GroundTask &robot,
                                      const ground::GroundTask &human, Case which,
                                      const GraphLimits &limits);

} // namespace envdesign::design
