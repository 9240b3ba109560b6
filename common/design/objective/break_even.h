#pragma once
// Break-even: how far the horizon T or the weight alpha can move before the chosen design
// stops being the best among a set of evaluated designs (design_point.h).
//
// Evaluations do not depend on T or alpha, so every evaluated design's objective is known
// for any T and alpha, and the answers below are exact statements about that set:
//   - horizon_down: the largest T < T0 at which some design of the set ranks before the
//     chosen one (SPEC.md's order, ties included); for every T in (horizon_down, T0] the
//     chosen design ranks first in the set. Unset: none for T in [1, T0).
//   - horizon_up: the least T > T0 at which one does; unset: none up to `horizon_limit`.
//   - alpha_down / alpha_up: objectives are linear in alpha, alpha * f_T(E[IE]) + rest, so
//     each design whose E[IE] differs from the chosen one's crosses it at one alpha. alpha_up
//     is the least crossing above alpha0 (designs more explicable than the chosen one win
//     beyond it), alpha_down the largest crossing below alpha0 (designs less explicable win
//     below it). At the crossing itself the two tie and the tie-breaks decide.
// Designs outside the set (never evaluated, because at the spec's weights the search's
// bounds proved they could not win) may overtake the chosen design earlier: so the chosen
// design certainly stops being the best at the reported values (a named design beats it),
// and may stop sooner.

#include "design/objective/design_point.h"

#include <optional>
#include <vector>

namespace envdesign::design {

struct Crossing {
    double at = 0;     // the horizon T (integral) or the weight alpha
    DesignPoint rival; // the design that ranks before the chosen one there
};

struct BreakEven {
    std::optional<Crossing> horizon_down;
    std::optional<Crossing> horizon_up;
    int horizon_limit = 0; // horizon_up was looked for in (T0, horizon_limit]
    std::optional<Crossing> alpha_down;
    std::optional<Crossing> alpha_up;
    long long designs_compared = 0; // the size of the set, the chosen design included
};

// `chosen` must be in `designs` or not; it is never its own rival. An infinite objective of
// the chosen design gives no crossing.
BreakEven break_even(const ObjectiveWeights &weights, const DesignPoint &chosen,
                     const std::vector<DesignPoint> &designs);

} // namespace envdesign::design
