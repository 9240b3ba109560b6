#pragma once
// Why the chosen design is the answer, as values (presentation is the clients' business). Not
// the robot explaining itself to people (robot_behaviour EXPLAINING: minimal_explanation.h).
//   - the objective's terms and the least inexplicability term possible (every IE at its
//     least: 1 for EXP_COST_DIFF, 0 for COST_DIFF), so that a reader can tell "as explicable
//     as it gets" from "still inexplicable";
//   - per task, the empty design and the chosen one side by side, and three plans under the
//     chosen design: the robot's optimal plan (P_R), the most explicable plan (pi) and the
//     plan observers expect (an optimal plan of P_H);
//   - the marginal value of each chosen modification: the chosen design without it,
//     evaluated through the search's own evaluator (stored evaluations and cached plans are
//     reused, nothing is planned twice);
//   - the points of the ranked designs (for plots against T and alpha);
//   - break-even (break_even.h) among every design evaluated in full.
//
//   EvaluationLog log(problem, evaluator);
//   DesignResult result = search_design(problem, log, options);
//   DesignExplanation why = explain_design(problem, result, log, &evaluator.planner(), deadline);

#include "design/evaluation/evaluation_log.h"
#include "design/evaluation/plan_cache.h"
#include "design/objective/break_even.h"
#include "design/search/design_search.h"

#include <optional>
#include <string>
#include <vector>

namespace envdesign::design {

struct TaskComparison {
    TaskExplicability baseline; // under the empty design (status LIMIT: not known)
    TaskExplicability chosen;   // under the chosen design
    // Under the chosen design: an optimal plan of P_R and its cost (INF: P_R has no plan);
    // unset when not solved (no planner given, or out of time).
    std::optional<std::vector<std::string>> robot_plan;
    std::optional<double> robot_optimal_cost;
    // Under the chosen design: an optimal plan of P_H, the plan observers expect.
    std::optional<std::vector<std::string>> expected_plan;
};

struct MarginalValue {
    int modification = 0;               // index into problem.modifications
    std::optional<DesignPoint> without; // the chosen design without it; unset: not evaluated
};

struct DesignExplanation {
    ObjectiveWeights weights;
    double discounted_horizon = 0;    // f_T(1)
    double least_ie = 1;              // 1 (EXP_COST_DIFF) or 0 (COST_DIFF)
    double least_inexplicability = 0; // f_T(least_ie): the term when every IE is least
    DesignPoint chosen;
    std::vector<TaskComparison> tasks;   // one per task of the problem
    std::vector<MarginalValue> marginal; // one per chosen modification, spec order
    std::vector<DesignPoint> ranking;    // result.ranking's designs (or the chosen one), best first
    BreakEven break_even;
};

// The explanation of result.best (which must be set). Designs it needs and the log lacks
// (the empty design, the chosen design minus one modification, ranked designs) are
// evaluated through `log` until `deadline`; `planner` (may be null) solves P_R, and P_H
// when the evaluation did not keep its plan.
DesignExplanation explain_design(const DesignProblem &problem, const DesignResult &result,
                                 EvaluationLog &log, PlanCache *planner, const Deadline &deadline);

} // namespace envdesign::design
