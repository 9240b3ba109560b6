#include "design/behaviour/evaluate_task.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/cost_optimal.h"
#include "design/behaviour/explaining.h"
#include "design/behaviour/explicability.h"

namespace envdesign::design {

TaskExplicability evaluate_task_behaviour(const ModelPair &models, const ObjectiveWeights &weights,
                                          PlanCache &planner, const Deadline &deadline) {
    const Behaviour &b = behaviour_of(weights.behaviour);
    if (b.runs_an_optimal_plan)
        return evaluate_cost_optimal(models, weights, planner, deadline);
    if (b.may_explain)
        return evaluate_explaining(models, weights, planner, deadline);
    return evaluate_explicability(models, weights.distance, planner, deadline);
}

} // namespace envdesign::design
