#pragma once
// The search over configurations (the paper's "Search for Optimal Design", made exact).
//
// search_design picks the search: the witness search (witness_search.h) by default, the
// hitting-set phase alone for the explaining robot where it applies, and the exhaustive
// search (exhaustive_search.h) for --search exhaustive, --prune relevant and where nothing
// faster is exact. Every search gives the same design and objective; the exhaustive one is
// the cross-check the tests compare the others with.

#include "design/search/design_result.h"

#include <functional>

namespace envdesign::design {

DesignResult search_design(const DesignProblem &problem, Evaluator &evaluator,
                           const DesignSearchOptions &options,
                           const std::function<void(const SearchProgress &)> &progress = {});

} // namespace envdesign::design
