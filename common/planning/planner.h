#pragma once
// The planner as one call: PDDL files in, an optimal plan (or a proof there is none) out,
// with the time spent in each phase. The `plan` command and the design engine both use it.

#include "ground/ground_task.h"
#include "heuristics/heuristic.h"
#include "search/astar_search.h"

#include <string>
#include <vector>

namespace envdesign::planning {

struct PlannerOptions {
    heuristics::HeuristicKind heuristic = heuristics::HeuristicKind::LMCUT;
    search::SearchLimits limits;
    // LM-cut's estimates inherited from the parent (search/inherited_lmcut.h): the same
    // optimal cost for a fraction of the time, but possibly another optimal plan.
    bool inherit_cuts = false;
};

struct PlanReport {
    search::SearchStatus status = search::SearchStatus::FAILED;
    std::vector<std::string> plan; // "(move a b)", in order
    long long cost = 0;
    long long secondary_cost = 0; // of the plan, among plans of least `cost`
    bool unit_cost = true;
    search::SearchStatistics statistics;
    int facts = 0;
    int operators = 0;
    double parse_seconds = 0;
    double ground_seconds = 0;
    double search_seconds = 0;
    double total_seconds = 0;
};

// Throws pddl::ParseError for bad input.
PlanReport plan_files(const std::string &domain_file, const std::string &problem_file,
                      const PlannerOptions &options);

// Searches an already ground task; parse and ground times are left at zero.
PlanReport plan_task(const ground::GroundTask &task, const PlannerOptions &options);

} // namespace envdesign::planning
