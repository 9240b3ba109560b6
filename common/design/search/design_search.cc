#include "design/search/design_search.h"

#include "design/behaviour/behaviour.h"
#include "design/search/exhaustive_search.h"
#include "design/search/witness_learning.h"
#include "design/search/witness_search.h"

namespace envdesign::design {

DesignResult search_design(const DesignProblem &problem, Evaluator &evaluator,
                           const DesignSearchOptions &options,
                           const std::function<void(const SearchProgress &)> &progress) {
    // EXPLAINING: a task's value depends on every difference between its two models (the
    // explanation), not only on its witness plans, so the witness argument does not hold;
    // the exhaustive search (with its bounds, which do hold) stays exact.
    bool explaining = !behaviour_of(problem.weights.behaviour).value_follows_witnesses;
    bool witness = options.method == SearchMethod::WITNESS && !options.relevant;
    std::optional<DesignResult> proven;
    if (witness && explaining && witness::explaining_applies(problem, TouchIndex(problem), options))
        proven = search_explaining_by_hitting_sets(problem, evaluator, options, progress);
    DesignResult result = proven       ? std::move(*proven)
                          : !witness   ? search_exhaustive(problem, evaluator, options, progress)
                          : explaining ? search_every_design(problem, evaluator, options, progress)
                                       : search_witness(problem, evaluator, options, progress);
    if (witness && explaining && !proven)
        result.notes.push_back("robot_behaviour EXPLAINING: the witness search does not apply "
                               "(explanations depend on every model difference); every design "
                               "was weighed, least bound first (docs/design-search.md)");
    else if (proven)
        result.notes.push_back("robot_behaviour EXPLAINING: no design is grown by its witnesses "
                               "(explanations depend on every model difference); the hitting-set "
                               "phase bounds explaining by the differences that must be told "
                               "(docs/design-search.md)");
    if (options.ranking > 1 && !options.ranking_all)
        result.notes.push_back(RANKING_NOTE);
    return result;
}

} // namespace envdesign::design
