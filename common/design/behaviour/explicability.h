#pragma once
// The explicability of one task under one configuration (SPEC.md, "The model"):
//   pi   = an optimal plan of P_mod (compilation.h): a most explicable plan, and among
//          those the cheapest for the robot;
//   c_H* = the optimal cost of P_H;
//   IE   = exp(|c_H(pi) - c_H*|) (EXP_COST_DIFF) or |c_H(pi) - c_H*| (COST_DIFF);
//          infinite when P_mod has no plan.
// P_H is solved first: where its optimal plan is valid in P_mod, both models charge alike and
// P_mod knows no object people do not, that plan is most explicable and P_mod is not searched.
//
// Example:
//   PlanCache planner(planning::PlannerOptions{});
//   TaskExplicability e = evaluate_explicability(models, Distance::EXP_COST_DIFF, planner, {});

#include "design/design_problem.h"
#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/search/deadline.h"

namespace envdesign::design {

// The planner's answer for one lifted model: skips grounding when the model was seen
// (PlanCache::solve_model with lifted_key.h).
PlanOutcome solve_model(const pddl::Domain &domain, const pddl::Problem &problem,
                        PlanCache &planner, const Deadline &deadline,
                        PlanChoice choice = PlanChoice::ANY_OPTIMAL);

// IE from the two human costs.
double inexplicability(double human_plan_cost, double human_optimal_cost, Distance distance);

// The least IE `distance` allows (a plan observers expect): 1 for EXP_COST_DIFF, 0 for
// COST_DIFF. The one definition the objective, the bounds and the explanation use.
double least_ie(Distance distance);

// A lower bound on a task's IE from the two models' optimal costs alone, where people's cost
// of every action is at least the robot's (human_costs_dominate, compilation.h): every plan
// the robot may follow costs people at least c_R*, so IE >= g(c_R* - c_H*). That holds for
// the most explicable plan and for every optimal plan of the COST_OPTIMAL robots. The
// explaining robot may explain instead; but above the least IE its own plan pi_R costs
// people more than c_H*, so an explanation tells at least one difference (the objective's
// bound takes the cheaper of the two). The least IE when c_R* <= c_H* or either is unknown.
double ie_floor(double robot_optimal_cost, double human_optimal_cost, Distance distance);
// Whether ie_floor holds in every task of `problem` (human_costs_dominate in each).
bool ie_floors_hold(const DesignProblem &problem);

// Compiles and grounds P_mod and P_H of `models` and plans both through `planner`.
// `solve_human_anyway`: report c_H* when P_mod has no plan too.
// Throws pddl::ParseError if the models cannot be compiled or grounded.
TaskExplicability evaluate_explicability(const ModelPair &models, Distance distance,
                                         PlanCache &planner, const Deadline &deadline,
                                         bool solve_human_anyway = false);

} // namespace envdesign::design
