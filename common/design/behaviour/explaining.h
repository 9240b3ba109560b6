#pragma once
// robot_behaviour EXPLAINING (SPEC.md): per task, the robot either acts explicably (the
// paper: it follows the most explicable plan pi) or follows its own optimal plan pi_R and
// explains it to the observers with a minimal explanation E (minimal_explanation.h). New observers
// need the explanation again, so it is paid on every repetition, discounted like IE.
//
// Per task t (probability p_t, H = (1 - gamma^T) / (1 - gamma), or T when gamma = 1), the
// two options contribute to the objective
//   act explicably: p_t * (alpha * H * IE_t                + kappa * T * c_R(pi))
//   explain:        p_t * (alpha * H * IE_least + H * x * |E| + kappa * T * c_R*)
// with x = explanation_cost and IE_least = 1 (EXP_COST_DIFF) or 0 (COST_DIFF): after E, pi_R
// is optimal for the observers. The robot takes the smaller (acting explicably on a tie:
// nothing to tell). An option is infinite when it has no plan (P_mod, or P_R, or no E).
// Since the objective is a sum over tasks of these contributions, choosing per task
// minimises it:
//   objective = alpha * f_T(E_D[IE']) + beta * C + kappa * T * E_D[c_R'] + f_T(E_D[x * |E'|])
// where IE', c_R', |E'| are the chosen option's values (|E'| = 0 when acting explicably).
// The choice does not depend on p_t, so evaluations keep both options and the objective
// chooses (choose_behaviour, objective.h: stored evaluations serve any weights and any
// distribution).

#include "design/behaviour/behaviour.h"
#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/objective/objective.h"
#include "design/search/deadline.h"

namespace envdesign::design {

// Which of P_R's optimal plans the robot of `behaviour` follows where it does not act
// explicably: the planner's (PLANNERS) for the explaining robot, which explains that very plan;
// for the others, only c_R* counts (ANY_OPTIMAL).
PlanChoice robot_plan_choice(const Behaviour &behaviour);

// Both options: evaluate_explicability, and the robot's optimal plan with a minimal
// explanation of it (t.explanation). LIMIT (an empty evaluation) if the deadline passed.
TaskExplicability evaluate_explaining(const ModelPair &models, const ObjectiveWeights &weights,
                                      PlanCache &planner, const Deadline &deadline);

} // namespace envdesign::design
