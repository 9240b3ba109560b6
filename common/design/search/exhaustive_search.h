#pragma once
// The exhaustive search (`--search exhaustive`, and the cross-check of every faster search).
//
// Subsets of the candidate modifications are enumerated by size (0, 1, 2, ... up to
// max_design_size), and within a size in spec order, so the first answer is the unmodified
// environment and better designs follow while there is time. Configurations go to the
// Evaluator in batches. Work is skipped only when it provably cannot change the answer:
//   - a configuration whose design cost alone, with every IE at its least value (1, or 0 for
//     COST_DIFF) and robot cost 0, already exceeds the best objective is not evaluated;
//   - once the cheapest subset of the next sizes cannot beat the best, the search ends:
//     design cost only grows with the subset when costs are non-negative (the bound takes the
//     cheapest subset of every remaining size, so negative costs are safe too);
//   - a configuration being evaluated is abandoned as soon as the tasks known so far, with
//     the unknown ones at their least, exceed the best (Evaluator's `abandon`); the least
//     robot cost of an unknown task is the robot's own optimal cost when the evaluator
//     found it (the most explicable plan is a robot plan), so a configuration can be
//     dropped before any compiled task is solved;
//   - (in the evaluator) equal ground tasks are solved once (plan_cache.h), and the human's
//     task is not solved when the compiled one has no plan.
// With --prune relevant (options.relevant set) the search instead grows configurations
// layer by layer, adding to each only the modifications relevant to its plans
// (relevance.h); the same bounds apply.
// The result is "optimal" only when every configuration was evaluated or skipped by these
// bounds, no planner hit the time limit, and the pruning left no configuration out.
// With options.ranking = N the result also lists the N best designs, and every bound above
// compares with the N-th best objective found instead of the best (ranking.h).

#include "design/search/design_result.h"

#include <functional>

namespace envdesign::design {

DesignResult search_exhaustive(const DesignProblem &problem, Evaluator &evaluator,
                               const DesignSearchOptions &options,
                               const std::function<void(const SearchProgress &)> &progress = {});

} // namespace envdesign::design
