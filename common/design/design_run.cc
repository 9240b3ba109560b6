#include "design/design_run.h"

#include "design/evaluation/relevance.h"
#include "design/evaluation/unsolvable_tasks.h"

#include <algorithm>

namespace envdesign::design {
namespace {

// How long the unsolvable tasks' reasons may plan: each is one or two plans of the
// unmodified models, so this only bites on a task the planner cannot finish.
constexpr double UNSOLVABLE_CHECK_S = 10;

Deadline stopping_at(Deadline deadline, const RunSettings &settings) {
    return settings.stop ? deadline.with_stop(settings.stop) : deadline;
}

} // namespace

DesignSearchOptions search_options(const DesignProblem &problem, const RunSettings &settings) {
    DesignSearchOptions options;
    options.method = settings.method;
    options.max_design_size =
        settings.max_design_size >= 0 ? settings.max_design_size : problem.max_design_size;
    double seconds = settings.time_limit_s >= 0 ? settings.time_limit_s : problem.time_limit_s;
    double cap = settings.max_time_limit_s;
    if (cap > 0 && (seconds <= 0 || seconds > cap))
        seconds = cap; // 0 was "no limit"
    options.deadline = stopping_at(Deadline::in(seconds), settings);
    options.batch_size = std::max(1, settings.batch_size);
    options.ranking = settings.ranking;
    options.ranking_all = settings.ranking_all;
    return options;
}

std::optional<DesignExplanation> explain_answer(const DesignProblem &problem,
                                                const DesignResult &result, EvaluationLog &log,
                                                PlanCache *planner,
                                                const Deadline &search_deadline) {
    if (!result.best)
        return std::nullopt;
    constexpr double AT_LEAST_S = 5;
    Deadline deadline;
    if (search_deadline.expired())
        deadline = Deadline::in(AT_LEAST_S);
    else if (search_deadline.limited())
        deadline = Deadline::in(std::max(search_deadline.remaining_seconds(), AT_LEAST_S));
    return explain_design(problem, result, log, planner, deadline);
}

DesignRun run_design(const DesignProblem &problem, EvaluationLog &log, PlanCache *planner,
                     const RunSettings &settings,
                     const std::function<void(const SearchProgress &)> &progress) {
    DesignSearchOptions options = search_options(problem, settings);
    if (settings.prune_relevant && planner)
        options.relevant = [&](const Configuration &c) {
            return settings.stop && settings.stop->load()
                       ? std::vector<int>{}
                       : relevant_modifications(problem, c, *planner, options.deadline);
        };
    DesignRun run;
    run.result = search_design(problem, log, options, progress);
    run.warnings = problem.warnings;
    const bool stopped = settings.stop && settings.stop->load();
    if (stopped && !settings.explain_when_stopped)
        return run;
    if (planner && run.result.baseline) {
        auto lines =
            unsolvable_task_warnings(problem, run.result.baseline->tasks, *planner,
                                     stopping_at(Deadline::in(UNSOLVABLE_CHECK_S), settings));
        run.warnings.insert(run.warnings.end(), lines.begin(), lines.end());
    }
    run.explanation = explain_answer(problem, run.result, log, planner, options.deadline);
    return run;
}

} // namespace envdesign::design
