#pragma once
// The design objective (SPEC.md, "The model"):
//   objective(xi) = alpha * f_T(E_D[IE]) + beta * C(xi) + kappa * T * E_D[c_R(pi)],
//   f_T(x) = x * (1 - gamma^T) / (1 - gamma), and T * x when gamma = 1.
// A task of positive probability with infinite IE makes the objective infinite, whatever
// the weights; tasks of probability 0 do not count.
//
// Ranking (ranks_before): lower objective, then fewer modifications, then lower C(xi), then
// the earlier modifications in spec order.
// robot_behaviour EXPLAINING: per task the cheaper of acting explicably and explaining counts
// (explaining.h), and the objective adds terms.explanation. Objectives within a relative 1e-9 of
// each other are equal, so that rounding in the sums cannot override the tie-breaking rules.

#include "design/behaviour/explicability.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"

#include <optional>
#include <vector>

namespace envdesign::design {

struct BehaviourChoice {
    bool finite = false;     // the chosen option has a plan
    bool explained = false;  // true: explain, false: act explicably
    double ie = INF;         // the IE that counts
    double robot_cost = INF; // c_R(pi), or c_R* when explained
    double explanation = 0;  // x * |E| when explained, per repetition; else 0
};

// The option the robot takes in task `t` (SOLVED or INEXPLICABLE): with EXPLAINING the
// cheaper of acting explicably and explaining (explaining.h; acting on a tie); otherwise, or
// without an explanation, acting explicably.
BehaviourChoice choose_behaviour(const ObjectiveWeights &weights, const TaskExplicability &t);

struct ObjectiveTerms {
    double inexplicability = INF; // f_T(E[IE])
    double design_cost = 0;       // C(xi)
    double robot_cost = INF;      // T * E[c_R(pi)]
    double explanation = 0;       // EXPLAINING: f_T(E[x * |E|]) (explaining.h); weight 1
};

struct Objective {
    double value = INF;
    ObjectiveTerms terms;
};

// (1 - gamma^T) / (1 - gamma), or T when gamma = 1: f_T(x) = x * discounted_horizon.
double discounted_horizon(const ObjectiveWeights &weights);
// The objective of `terms` under `weights` (formula.h): the one weighted sum.
double objective_value(const ObjectiveWeights &weights, const ObjectiveTerms &terms);

// `tasks` holds one evaluation per task of `problem`, all SOLVED or INEXPLICABLE.
Objective objective_of(const DesignProblem &problem, double design_cost,
                       const std::vector<TaskExplicability> &tasks);

// The same sum with the weights and probabilities given apart (design points re-weigh
// stored evaluations under other weights, design_point.h): `probabilities[i]` of `tasks[i]`.
Objective objective_of(const ObjectiveWeights &weights, double design_cost,
                       const std::vector<double> &probabilities,
                       const std::vector<TaskExplicability> &tasks);

// A lower bound on the objective when only some tasks are known (`known[i]` null: task i
// not evaluated yet): unknown tasks count with IE `ie_floors[i]` when given, else the least
// IE the distance allows (1 or 0), and robot cost `robot_cost_bounds[i]` when given (INF:
// the robot has no plan, so neither has P_mod), else 0. With no task known and no floor it
// bounds every configuration of that design cost.
double objective_lower_bound(const DesignProblem &problem, double design_cost,
                             const std::vector<const TaskExplicability *> &known,
                             const std::vector<std::optional<double>> &robot_cost_bounds = {},
                             const std::vector<std::optional<double>> &ie_floors = {},
                             const std::vector<std::optional<int>> &explanation_floors = {});

// a == b within a relative 1e-9 (infinities equal each other only).
bool nearly_equal(double a, double b);
// a > b and not nearly equal: b certainly ranks before anything whose objective is a.
bool clearly_greater(double a, double b);

struct RankedDesign {
    double objective = INF;
    double design_cost = 0;
    Configuration configuration;
};

// The total order of SPEC.md's tie-breaking rules.
bool ranks_before(const RankedDesign &a, const RankedDesign &b);

} // namespace envdesign::design
