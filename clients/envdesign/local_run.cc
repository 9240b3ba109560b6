#include "local_run.h"

#include "cluster/result_message.h"
#include "design/design_spec.h"
#include "design/explanation.h"
#include "heuristics/heuristic.h"
#include "pddl/parse_error.h"

#include <algorithm>
#include <iostream>

namespace envdesign::cli {
namespace {

planning::PlannerOptions planner_options(const std::string &heuristic) {
    planning::PlannerOptions options;
    options.heuristic = heuristics::parse_heuristic_kind(heuristic);
    return options;
}

design::Deadline explanation_deadline(const design::Deadline &search) {
    constexpr double AT_LEAST_S = 5;
    if (!search.limited())
        return {};
    return design::Deadline::in(std::max(search.remaining_seconds(), AT_LEAST_S));
}

} // namespace

LocalRun::LocalRun(const design::DesignProblem &problem, int workers, const std::string &heuristic)
    : problem_(problem), local_(problem, workers, planner_options(heuristic)),
      log_(problem, local_) {}

envdesign::design_result_t LocalRun::message(const design::DesignResult &result,
                                             const design::Deadline &search_deadline) {
    if (!result.best)
        return cluster::result_message(problem_, result, {});
    design::Explanation why = design::explain(problem_, result, log_, &local_.planner(),
                                              explanation_deadline(search_deadline));
    return cluster::result_message(problem_, result, {}, &why);
}

std::optional<design::DesignProblem> load_problem(const std::string &path) {
    try {
        return design::load_design_problem(path);
    } catch (const pddl::ParseError &e) {
        std::cerr << e.what() << std::endl;
        return std::nullopt;
    }
}

} // namespace envdesign::cli
