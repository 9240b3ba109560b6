#pragma once
// The in-process engine the local commands (design, evaluate, report) share: N planner
// threads (LocalEvaluator) behind an EvaluationLog, so that every design evaluated in full
// can be re-weighed by the explanation. The commands turn its runs into the message the
// coordinator sends (wire/result_message.h), so that one formatter prints both paths.

#include "design/design_run.h"
#include "design/evaluation/evaluation_log.h"
#include "design/evaluation/local_evaluator.h"

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

// The flags of the local engine, the same on design, evaluate and report: --workers,
// --time-limit (default: the spec's) and --heuristic.
void add_engine_flags(CLI::App &command, int &workers, double &time_limit_s,
                      std::string &heuristic);

class LocalRun {
public:
    // `problem` must outlive the run.
    LocalRun(const design::DesignProblem &problem, int workers, const std::string &heuristic);

    design::Evaluator &evaluator() { return log_; }
    design::LocalEvaluator &local() { return local_; }

    // One design run (design/design_run.h) on these planners: the search, the explanation
    // of its answer and the warnings.
    design::DesignRun run(const design::RunSettings &settings,
                          const std::function<void(const design::SearchProgress &)> &progress = {});
    // `result` (one design evaluated, not searched) explained as a run's answer is, with the
    // spec's warnings.
    design::DesignRun explained(design::DesignResult result, const design::Deadline &deadline);

private:
    const design::DesignProblem &problem_;
    design::LocalEvaluator local_;
    design::EvaluationLog log_;
};

} // namespace envdesign::cli
