#include "local_run.h"

#include "heuristics/heuristic.h"
#include "service/number_flag.h"

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

} // namespace

LocalRun::LocalRun(const design::DesignProblem &problem, int workers, const std::string &heuristic)
    : problem_(problem), local_(problem, workers, planner_options(heuristic)),
      log_(problem, local_) {}

design::DesignRun
LocalRun::run(const design::RunSettings &settings,
              const std::function<void(const design::SearchProgress &)> &progress) {
    return design::run_design(problem_, log_, &local_.planner(), settings, progress);
}

design::DesignRun LocalRun::explained(design::DesignResult result,
                                      const design::Deadline &deadline) {
    design::DesignRun run;
    run.result = std::move(result);
    run.warnings = problem_.warnings;
    run.explanation =
        design::explain_answer(problem_, run.result, log_, &local_.planner(), deadline);
    return run;
}

} // namespace envdesign::cli
