#include "planning/planner.h"

#include "ground/grounder.h"
#include "pddl/parser.h"

#include <chrono>

namespace envdesign::planning {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PlanReport plan_task(const ground::GroundTask &task, const PlannerOptions &options) {
    auto start = std::chrono::steady_clock::now();
    search::SearchResult result = search::astar(task, options.heuristic, options.limits);
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
    auto ground_start = std::chrono::steady_clock::now();
    ground::GroundTask task = ground::ground(domain, problem);
    double ground_seconds = seconds_since(ground_start);
    PlanReport report = plan_task(task, options);
    report.parse_seconds = parse_seconds;
    report.ground_seconds = ground_seconds;
    report.total_seconds = seconds_since(start);
    return report;
}

}  // namespace envdesign::planning
