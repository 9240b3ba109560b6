#include "design_warnings.h"

#include "design/unsolvable_tasks.h"
#include "spec/design_spec.h"

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
        // Parsed only (the coordinator checks the rest): the warnings are the loader's.
        spec::SpecFile spec = spec::read_spec_file(spec_path);
        return spec::load_design_problem(spec, spec::DiskFiles(spec.path),
                                         spec::Checks::TRUSTED_BY_HASH)
            .warnings;
    } catch (const pddl::ParseError &) { // the coordinator's answer names it
    }
    return {};
}

std::vector<std::string> remote_unsolvable_task_warnings(const std::string &spec_path,
                                                         const std::string &result_json,
                                                         const design::Deadline &deadline) {
    auto result = nlohmann::json::parse(result_json, nullptr, false);
    if (result.is_discarded() || !result.contains("explanation"))
        return {};
    const auto &tasks = result["explanation"].value("tasks", nlohmann::json::array());
    bool any = false;
    for (const auto &t : tasks)
        any = any || (t.contains("baseline") && t["baseline"].is_object() &&
                      t["baseline"].value("ie", nlohmann::json()) == "inf");
    if (!any)
        return {};
    try {
        design::DesignProblem problem = spec::load_design_problem(spec_path);
        if (tasks.size() != problem.tasks.size())
            return {};
        design::DesignResult known;
        known.baseline.emplace();
        for (const auto &t : tasks) {
            design::TaskExplicability e;
            bool infinite =
                t["baseline"].is_object() && t["baseline"].value("ie", nlohmann::json()) == "inf";
            e.status = infinite ? design::ExplicabilityStatus::INEXPLICABLE
                                : design::ExplicabilityStatus::SOLVED;
            known.baseline->tasks.push_back(e);
        }
        design::PlanCache planner(planning::PlannerOptions{});
        return unsolvable_task_warnings(problem, known, planner, deadline);
    } catch (const pddl::ParseError &) { // the coordinator's answer names it
        return {};
    }
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
