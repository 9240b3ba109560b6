#include "design_warnings.h"

#include "design/design_spec.h"
#include "design/unsolvable_tasks.h"

#include <nlohmann/json.hpp>

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

std::vector<std::string> remote_spec_warnings(const std::string &spec_path) {
    try {
        if (auto warning = design::probability_warning(design::read_spec_file(spec_path)))
            return {*warning};
    } catch (const pddl::ParseError &) { // the coordinator's answer names it
    }
    return {};
}

std::string with_warnings(const std::string &json_text, const std::vector<std::string> &warnings) {
    if (warnings.empty())
        return json_text;
    nlohmann::json out = nlohmann::json::parse(json_text);
    out["warnings"] = warnings;
    return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void print_warnings(const std::vector<std::string> &warnings) {
    for (const auto &line : warnings)
        std::cerr << (line.find(": warning: ") == std::string::npos ? "warning: " : "") << line
                  << "\n";
}

} // namespace envdesign::cli
