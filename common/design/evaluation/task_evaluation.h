#pragma once
// One task's evaluation under one configuration, as a plain value: what crosses the
// Evaluator boundary (evaluator.h), the wire and the evaluation store. No planner here.
//
//   plan       = pi, a most explicable plan (an optimal plan of P_mod);
//   human_plan = an optimal plan of P_H, the plan observers expect.
// Both are the witnesses of the evaluation: the design search (witness_search.h) keeps an
// evaluation for a larger configuration when no added modification touches them.

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::design {

inline constexpr double INF = std::numeric_limits<double>::infinity();

enum class ExplicabilityStatus {
    SOLVED,       // a most explicable plan was found
    INEXPLICABLE, // P_mod (or P_H) has no plan: IE is infinite
    LIMIT,        // the deadline passed first: nothing is known
};

// robot_behaviour EXPLAINING (minimal_explanation.h): the robot's own optimal plan pi_R and a
// minimal set of model differences that, told to the observers, makes pi_R optimal in their model.
struct TaskExplanation {
    bool found = false;                   // false: no subset works (or P_R has no plan)
    double robot_optimal_cost = INF;      // c_R*, the cost of pi_R; INF: P_R has no plan
    std::vector<std::string> robot_plan;  // pi_R, the planner's optimal plan of P_R
    std::vector<std::string> differences; // E, model_differences.h's text, smallest first
};

struct TaskExplicability {
    ExplicabilityStatus status = ExplicabilityStatus::LIMIT;
    double ie = INF;
    double robot_cost = INF;                  // c_R(pi)
    double human_plan_cost = INF;             // c_H(pi)
    std::optional<double> human_optimal_cost; // c_H*; INF if P_H has no plan; unset if not solved
    std::vector<std::string> plan;            // pi, "(move c00 c10)" ...
    // An optimal plan of P_H when one was found and kept; unset: not known (P_H unsolved,
    // or the evaluation came from somewhere that did not keep it).
    std::optional<std::vector<std::string>> human_plan;
    // Set when the spec's robot_behaviour is EXPLAINING: the other option of the task
    // (explaining.h chooses between acting explicably and explaining).
    std::optional<TaskExplanation> explanation;
    // COST_OPTIMAL and COST_OPTIMAL_BEST_CASE: every ground action of some cost-optimal plan
    // of P_R, sorted, unique. These are the evaluation's robot witnesses there (all optimal
    // plans count, not only `plan`): a restricting modification touching none of them keeps
    // the set of optimal plans (witness.h). Unset: not known.
    std::optional<std::vector<std::string>> optimal_actions;
};

} // namespace envdesign::design
