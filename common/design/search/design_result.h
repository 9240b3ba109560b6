#pragma once
// What the design searches share (design_search.h, witness_search.h): their options, the
// progress they report, and the result, with the helpers every search uses to fill it.

#include "design/design_problem.h"
#include "design/evaluation/evaluator.h"
#include "design/objective/objective.h"
#include "design/search/ranking.h"

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::design {

enum class SearchMethod {
    WITNESS,    // the default: grows designs only by modifications that touch a witness
    EXHAUSTIVE, // every subset (the cross-check)
};

struct DesignSearchOptions {
    SearchMethod method = SearchMethod::WITNESS;
    int max_design_size = 0; // 0: no limit
    Deadline deadline;
    // --prune relevant: the modifications worth adding to a configuration (relevance.h);
    // empty: every subset is a candidate (exact).
    std::function<std::vector<int>(const Configuration &)> relevant;
    int batch_size = 8; // configurations per evaluate() call
    // Witness search: try the hitting-set phase (hitting_set.h) before the best-first
    // search; off only to test or measure the best-first search alone.
    bool hitting_sets = true;
    // The N best designs, best first, in ranks_before order (DesignResult::ranking); 0 or 1:
    // only the best. The searches then prune against the N-th best found so far.
    int ranking = 0;
    // Padded designs (a modification that does not pay for itself, ranking.h) in the ranking
    // too (--ranking-all); by default they are left out and a note says so.
    bool ranking_all = false;
};

struct SearchProgress {
    long long done = 0;  // configurations evaluated, abandoned or skipped
    long long total = 0; // configurations in the search space (witness, --prune: generated so far)
    double best_objective = INF;
    long long planner_runs = 0;
    long long cache_hits = 0;
    long long open = -1;           // witness search: configurations waiting; -1: not kept
    double least_open_bound = INF; // witness search: the least bound among them
};

struct DesignCounters {
    long long configurations_total = 0;     // subsets of the modifications up to the size limit
    long long configurations_evaluated = 0; // fully evaluated
    long long configurations_abandoned = 0; // dropped part-way by the bound
    long long configurations_skipped = 0;   // never started: the bound excluded them
    long long configurations_pruned = 0;    // never generated: --prune relevant left them out
    long long tasks_inherited = 0;          // witness search: task evaluations kept from a subset
    long long configurations_probed = 0;    // witness search: designs evaluated to learn plans
                                            // (probes, and designs stored earlier)
    EvaluatorCounters evaluator;
    double seconds = 0;
};

struct EvaluatedDesign {
    RankedDesign ranked;
    Objective objective;
    std::vector<TaskExplicability> tasks;
};

struct DesignResult {
    bool optimal = false;                    // proven optimal for the spec
    bool limit_reached = false;              // the deadline stopped the search
    std::optional<EvaluatedDesign> best;     // unset only if not even {} was evaluated
    std::optional<EvaluatedDesign> baseline; // the empty design
    // The best designs found, best first (ranks_before), at most max(1, options.ranking);
    // proven the true best ones when `optimal`.
    std::vector<RankedDesign> ranking;
    // When a limit stopped the search: the best objective minus the least bound still open
    // (an optimal design is no better than best - gap).
    std::optional<double> gap;
    // Why the search had to look wider than the touched modifications (witness search):
    // modifications that are not restricting or cost less than nothing.
    std::vector<std::string> notes;
    DesignCounters counters;
};

// Shared by the searches: the evaluator's counters and the seconds since `start`.
void close_counters(DesignCounters &counters, const Evaluator &evaluator,
                    std::chrono::steady_clock::time_point start);

// Shared by the searches: the evaluated design `configuration` (every task known), whether
// it replaces result.best (and result.baseline for {}), and its place in `ranking`.
void consider_design(const DesignProblem &problem, const Configuration &configuration,
                     std::vector<TaskExplicability> tasks, DesignResult &result, Ranking &ranking);

// The objective a design must not clearly exceed to become the best or enter `ranking`
// (INF while either is still open).
double ranking_limit(const DesignResult &result, const Ranking &ranking);

// C(n, k), saturating at the largest long long.
long long binomial(long long n, long long k);

// A lower bound on the objective of `partial`'s configuration alone (design cost `cost`),
// from what its evaluation knows so far: tasks, robot bounds and floors.
double own_lower_bound(const DesignProblem &problem, double cost,
                       const ConfigurationEvaluation &partial);

} // namespace envdesign::design
