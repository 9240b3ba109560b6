#include "design_warnings.h"

#include "design/unsolvable_tasks.h"

#include <iostream>

namespace envdesign::cli {
namespace {

std::string reason_text(design::UnsolvableReason reason) {
    switch (reason) {
    case design::UnsolvableReason::ROBOT_HAS_NO_PLAN:
        return "P_R has no plan (the robot cannot do the task)";
    case design::UnsolvableReason::HUMAN_HAS_NO_PLAN:
        return "P_H has no plan (observers believe the task impossible)";
    case design::UnsolvableReason::NO_PLAN_VALID_IN_BOTH:
        return "no plan is valid in both P_R and P_H (P_mod has no plan)";
    }
    return "unknown";
}

} // namespace

std::vector<std::string> unsolvable_task_warnings(const design::DesignProblem &problem,
                                                  const design::DesignResult &result,
                                                  design::PlanCache &planner,
                                                  const design::Deadline &deadline) {
    std::vector<std::string> lines;
    if (!result.baseline)
        return lines;
    for (const auto &u :
         design::unsolvable_tasks(problem, result.baseline->tasks, planner, deadline))
        lines.push_back("task '" + problem.tasks[u.task].name +
                        "' has infinite IE in the unmodified models: " + reason_text(u.reason));
    return lines;
}

void print_warnings(const std::vector<std::string> &warnings) {
    for (const auto &line : warnings)
        std::cerr << (line.find(": warning: ") == std::string::npos ? "warning: " : "") << line
                  << "\n";
}

} // namespace envdesign::cli
