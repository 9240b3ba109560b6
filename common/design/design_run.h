#pragma once
// One design run, as every entry point runs it (the CLI's design and report, the
// coordinator's request, the arrivals re-designer and so the bridge): the search settings
// resolved against the spec's, the search, the explanation of its answer and the warnings a
// user should read beside it (the spec's, and the tasks no design can make explicable).
//
//   LocalEvaluator local(problem, workers);
//   EvaluationLog log(problem, local);
//   RunSettings settings;
//   settings.time_limit_s = 30;                  // overrides the spec's
//   DesignRun run = run_design(problem, log, &local.planner(), settings);
//   run.result.best, run.explanation, run.warnings
//
// Presentation is the clients' (result_format.h); the message is wire/result_message.h.

#include "design/design_explanation.h"
#include "design/evaluation/evaluation_log.h"
#include "design/evaluation/plan_cache.h"
#include "design/search/design_search.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::design {

// What a caller may set of a run; the negative defaults take the spec's.
struct RunSettings {
    double time_limit_s = -1;    // < 0: the spec's; 0: none
    double max_time_limit_s = 0; // > 0: no run is longer, "none" included (the coordinator)
    int max_design_size = -1;    // < 0: the spec's; 0: no limit
    SearchMethod method = SearchMethod::WITNESS;
    bool prune_relevant = false; // --prune relevant (the paper's pruning; not exact)
    int ranking = 0;
    bool ranking_all = false;
    int batch_size = 8;
    // Once set, the search stops as at its deadline (Ctrl-C, a cancelled request).
    const std::atomic<bool> *stop = nullptr;
    // The answer of a stopped run is explained all the same (the CLI prints it); a cancelled
    // request's is not wanted.
    bool explain_when_stopped = true;
};

// The search options `settings` give for `problem` (the relevance pruning left unset: it
// needs a planner, run_design sets it).
DesignSearchOptions search_options(const DesignProblem &problem, const RunSettings &settings);

struct DesignRun {
    DesignResult result;
    std::optional<DesignExplanation> explanation; // of result.best, when explained
    // The spec's warnings (problem.warnings), then one per task whose IE is infinite in the
    // unmodified models, with the reason.
    std::vector<std::string> warnings;
};

// Searches `problem` through `log` (which keeps what the search evaluated, for the
// explanation), explains the answer and collects the warnings. `planner` (may be null: no
// planning past the search) serves --prune relevant, the explanation's plans and the
// unsolvable tasks' reasons. Bad models throw pddl::ParseError as search_design does.
DesignRun run_design(const DesignProblem &problem, EvaluationLog &log, PlanCache *planner,
                     const RunSettings &settings,
                     const std::function<void(const SearchProgress &)> &progress = {});

// The explanation of result.best (nullopt without one): the designs it needs are evaluated
// within the search's deadline, and at least a few seconds when the search used it up.
std::optional<DesignExplanation> explain_answer(const DesignProblem &problem,
                                                const DesignResult &result, EvaluationLog &log,
                                                PlanCache *planner,
                                                const Deadline &search_deadline);

} // namespace envdesign::design
