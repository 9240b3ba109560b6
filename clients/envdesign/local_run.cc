#include "local_run.h"

#include "cluster/result_message.h"
#include "design/design_explanation.h"
#include "heuristics/heuristic.h"
#include "service/number_flag.h"

#include <algorithm>

namespace envdesign::cli {

void add_engine_flags(CLI::App &command, int &workers, double &time_limit_s,
                      std::string &heuristic) {
    command.add_option("--workers", workers, "planner threads")->check(CLI::Range(1, 256));
    command.add_option("--time-limit", time_limit_s, "seconds (0: none; default: the spec's)")
        ->check(service::number_in(design::TIME_LIMIT_S));
    command.add_option("--heuristic", heuristic, "lmcut | hmax | blind")
        ->check(CLI::IsMember({"lmcut", "hmax", "blind"}));
}
namespace {

planning::PlannerOptions planner_options(const std::string &heuristic) {
    planning::PlannerOptions options;
    options.heuristic = heuristics::parse_heuristic_kind(heuristic);
    return options;
}

// The explanation evaluates a few designs the search may not have: within the search's time
// limit, and at least a few seconds when the search used it up or was interrupted (Ctrl-C
// prints soon, with what could be evaluated).
design::Deadline explanation_deadline(const design::Deadline &search) {
    constexpr double AT_LEAST_S = 5;
    if (search.expired())
        return design::Deadline::in(AT_LEAST_S);
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
    design::DesignExplanation why = design::explain_design(
        problem_, result, log_, &local_.planner(), explanation_deadline(search_deadline));
    return cluster::result_message(problem_, result, {}, &why);
}

} // namespace envdesign::cli
