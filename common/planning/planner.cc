#include "planning/planner.h"

#include "ground/grounder.h"
#include "pddl/parser.h"

#include <algorithm>
#include <chrono>

namespace envdesign::planning {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

PlanReport plan_task(const ground::GroundTask &task, const PlannerOptions &options) {
    auto start = std::chrono::steady_clock::now();
    search::SearchResult result =
        search::astar(task, options.heuristic, options.limits, options.inherit_cuts);
    PlanReport report;
    report.status = result.status;
    for (ground::OperatorId op : result.plan)
        report.plan.push_back(task.operators[op].name);
    report.cost = result.cost;
    report.secondary_cost = result.secondary_cost;
    report.unit_cost = !task.has_action_costs;
    report.statistics = result.stats;
    report.facts = task.num_facts();
    report.operators = task.num_operators();
    report.search_seconds = seconds_since(start);
    report.total_seconds = report.search_seconds;
    return report;
}

PlanReport plan_files(const std::string &domain_file, const std::string &problem_file,
                      const PlannerOptions &options) {
    auto start = std::chrono::steady_clock::now();
    pddl::Domain domain = pddl::parse_domain_file(domain_file);
    pddl::Problem problem = pddl::parse_problem_file(problem_file, domain);
    double parse_seconds = seconds_since(start);
    // The time limit covers grounding too; the search gets what is left.
    double limit = options.limits.time_limit_s;
    ground::StopCheck stop;
    if (limit > 0)
        stop = [&] { return seconds_since(start) >= limit; };
    auto ground_start = std::chrono::steady_clock::now();
    ground::GroundTask task;
    try {
        task = ground::ground(domain, problem, nullptr, stop);
    } catch (const ground::GroundingStopped &) {
        PlanReport report;
        report.status = search::SearchStatus::LIMIT;
        report.parse_seconds = parse_seconds;
        report.ground_seconds = seconds_since(ground_start);
        report.total_seconds = seconds_since(start);
        return report;
    }
    double ground_seconds = seconds_since(ground_start);
    PlannerOptions searching = options;
    if (limit > 0)
        searching.limits.time_limit_s = std::max(0.001, limit - seconds_since(start));
    PlanReport report = plan_task(task, searching);
    report.parse_seconds = parse_seconds;
    report.ground_seconds = ground_seconds;
    report.total_seconds = seconds_since(start);
    return report;
}

} // namespace envdesign::planning
