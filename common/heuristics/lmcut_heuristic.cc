#include "heuristics/lmcut_heuristic.h"

namespace envdesign::heuristics {

int LmCutHeuristic::compute(const StateView &state) {
    // No cut callback: the estimate needs only the sum, which compute() returns.
    return landmarks_.compute(state.facts());
}

} // namespace envdesign::heuristics
