#pragma once
// Why a task has infinite IE in the unmodified models (the baseline): so that an objective
// of "inf" comes with a reason a user can act on. In order of what is checked:
//   ROBOT_HAS_NO_PLAN      P_R has no plan: the robot cannot do the task at all;
//   HUMAN_HAS_NO_PLAN      P_H has no plan: observers believe the task impossible;
//   NO_PLAN_VALID_IN_BOTH  both have plans, but no plan is valid in both (P_mod has none).
//
// Example:
//   for (const UnsolvableTask &u : unsolvable_tasks(problem, result.baseline->tasks,
//                                                   evaluator.planner(), Deadline::in(5)))
//       report(problem.tasks[u.task].name, u.reason);   // the client words it

#include "design/design_problem.h"
#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/search/deadline.h"

#include <string>
#include <vector>

namespace envdesign::design {

enum class UnsolvableReason { ROBOT_HAS_NO_PLAN, HUMAN_HAS_NO_PLAN, NO_PLAN_VALID_IN_BOTH };

struct UnsolvableTask {
    int task = 0; // index into problem.tasks
    UnsolvableReason reason = UnsolvableReason::NO_PLAN_VALID_IN_BOTH;
};

// The tasks of `baseline` (the empty design's evaluations, one per task) that are
// INEXPLICABLE, with the reason. Plans P_R (and P_H when the evaluation did not solve it)
// through `planner`; a task whose check reaches `deadline` is left out.
std::vector<UnsolvableTask> unsolvable_tasks(const DesignProblem &problem,
                                             const std::vector<TaskExplicability> &baseline,
                                             PlanCache &planner, const Deadline &deadline);

// The same tasks as warning lines: "task 'NAME' has infinite IE in the unmodified models:
// REASON", the reason worded for a user.
std::vector<std::string> unsolvable_task_warnings(const DesignProblem &problem,
                                                  const std::vector<TaskExplicability> &baseline,
                                                  PlanCache &planner, const Deadline &deadline);

} // namespace envdesign::design
