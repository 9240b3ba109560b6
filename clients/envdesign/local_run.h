#pragma once
// The in-process engine the local commands (design, evaluate, report) share: N planner
// threads (LocalEvaluator) behind an EvaluationLog, so that every design evaluated in full
// can be re-weighed by the explanation, and the result as the message the coordinator sends
// (cluster/result_message.h), so that one formatter prints both paths.

#include "design/design_search.h"
#include "design/evaluation_log.h"
#include "design/local_evaluator.h"
#include "envdesign/design_result_t.hpp"

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

    // `result` with its explanation when it has a design. The explanation may evaluate a few
    // designs (the chosen one minus one modification) until the search's deadline, or a few
    // seconds past it when the search used it up.
    envdesign::design_result_t message(const design::DesignResult &result,
                                       const design::Deadline &search_deadline);

private:
    const design::DesignProblem &problem_;
    design::LocalEvaluator local_;
    design::EvaluationLog log_;
};

} // namespace envdesign::cli
