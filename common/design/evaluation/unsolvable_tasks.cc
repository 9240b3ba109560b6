#include "design/evaluation/unsolvable_tasks.h"

#include "design/behaviour/explaining.h"
#include "design/behaviour/explicability.h"
#include "design/model/configuration.h"

namespace envdesign::design {

std::vector<UnsolvableTask> unsolvable_tasks(const DesignProblem &problem,
                                             const std::vector<TaskExplicability> &baseline,
                                             PlanCache &planner, const Deadline &deadline) {
    std::vector<UnsolvableTask> found;
    for (std::size_t i = 0; i < baseline.size() && i < problem.tasks.size(); ++i) {
        if (baseline[i].status != ExplicabilityStatus::INEXPLICABLE)
            continue;
        ModelPair models = base_models(problem, static_cast<int>(i));
        // The choice the evaluations made: the robot's answer is then a cache hit.
        PlanOutcome robot =
            solve_model(models.robot_domain, models.robot_problem, planner, deadline,
                        robot_plan_choice(behaviour_of(problem.weights.behaviour)));
        if (robot.status == PlanStatus::LIMIT)
            continue;
        UnsolvableTask u{static_cast<int>(i), UnsolvableReason::NO_PLAN_VALID_IN_BOTH};
        if (robot.status == PlanStatus::UNSOLVABLE) {
            u.reason = UnsolvableReason::ROBOT_HAS_NO_PLAN;
        } else {
            // The evaluation knows c_H* when it solved P_H (INF: no plan); else solve it here.
            PlanStatus human = PlanStatus::SOLVED;
            if (!baseline[i].human_optimal_cost)
                human = solve_model(models.human_domain, models.human_problem, planner, deadline)
                            .status;
            else if (*baseline[i].human_optimal_cost == INF)
                human = PlanStatus::UNSOLVABLE;
            if (human == PlanStatus::LIMIT)
                continue;
            if (human == PlanStatus::UNSOLVABLE)
                u.reason = UnsolvableReason::HUMAN_HAS_NO_PLAN;
        }
        found.push_back(u);
    }
    return found;
}

namespace {

std::string reason_text(UnsolvableReason reason) {
    switch (reason) {
    case UnsolvableReason::ROBOT_HAS_NO_PLAN:
        return "P_R has no plan (the robot cannot do the task)";
    case UnsolvableReason::HUMAN_HAS_NO_PLAN:
        return "P_H has no plan (observers believe the task impossible)";
    case UnsolvableReason::NO_PLAN_VALID_IN_BOTH:
        return "no plan is valid in both P_R and P_H (P_mod has no plan)";
    }
    return "unknown";
}

} // namespace

std::vector<std::string> unsolvable_task_warnings(const DesignProblem &problem,
                                                  const std::vector<TaskExplicability> &baseline,
                                                  PlanCache &planner, const Deadline &deadline) {
    std::vector<std::string> lines;
    for (const UnsolvableTask &u : unsolvable_tasks(problem, baseline, planner, deadline))
        lines.push_back("task '" + problem.tasks[u.task].name +
                        "' has infinite IE in the unmodified models: " + reason_text(u.reason));
    return lines;
}

} // namespace envdesign::design
