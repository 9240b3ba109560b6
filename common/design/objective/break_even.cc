#include "design/objective/break_even.h"

#include <algorithm>
#include <cmath>

namespace envdesign::design {
namespace {

// Work bound for the horizon scans: designs x horizons looked at.
constexpr long long SCAN_BUDGET = 5'000'000; // about a second at most

// The first design of `rivals` that ranks before `chosen` at horizon T, if any.
const DesignPoint *winner_at(ObjectiveWeights weights, int horizon, const DesignPoint &chosen,
                             const std::vector<const DesignPoint *> &rivals) {
    weights.horizon = horizon;
    RankedDesign own = ranked_at(weights, chosen);
    const DesignPoint *best = nullptr;
    RankedDesign best_rank = own;
    for (const DesignPoint *r : rivals) {
        RankedDesign rank = ranked_at(weights, *r);
        if (ranks_before(rank, best_rank)) {
            best = r;
            best_rank = rank;
        }
    }
    return best;
}

void scan_horizons(const ObjectiveWeights &weights, const DesignPoint &chosen,
                   const std::vector<const DesignPoint *> &rivals, BreakEven &out) {
    long long per_step = std::max<long long>(1, static_cast<long long>(rivals.size()));
    long long steps = std::max<long long>(1, SCAN_BUDGET / per_step / 2);
    int t0 = weights.horizon;
    for (long long t = t0 - 1; t >= 1 && t0 - t <= steps; --t)
        if (const DesignPoint *r = winner_at(weights, static_cast<int>(t), chosen, rivals)) {
            out.horizon_down = Crossing{static_cast<double>(t), *r};
            break;
        }
    long long limit = std::min<long long>(
        {static_cast<long long>(t0) + steps, std::max<long long>(1000, 10LL * t0), 1LL << 30});
    out.horizon_limit = static_cast<int>(limit);
    for (long long t = t0 + 1; t <= limit; ++t)
        if (const DesignPoint *r = winner_at(weights, static_cast<int>(t), chosen, rivals)) {
            out.horizon_up = Crossing{static_cast<double>(t), *r};
            break;
        }
}

// objective = alpha * slope + offset: slope = f_T(E[IE]), offset = the other two terms.
void alpha_crossings(const ObjectiveWeights &weights, const DesignPoint &chosen,
                     const std::vector<const DesignPoint *> &rivals, BreakEven &out) {
    Objective own = objective_at(weights, chosen);
    double own_offset = own.value - weights.alpha * own.terms.inexplicability;
    for (const DesignPoint *r : rivals) {
        Objective theirs = objective_at(weights, *r);
        if (std::isinf(theirs.value))
            continue; // infinite for every alpha > 0
        double slope = theirs.terms.inexplicability - own.terms.inexplicability;
        if (slope == 0)
            continue; // parallel: the order does not change with alpha
        double offset = theirs.value - weights.alpha * theirs.terms.inexplicability - own_offset;
        double at = -offset / slope; // where alpha * slope + offset = 0
        if (slope < 0 && at >= weights.alpha && (!out.alpha_up || at < out.alpha_up->at))
            out.alpha_up = Crossing{at, *r};
        if (slope > 0 && at >= 0 && at <= weights.alpha &&
            (!out.alpha_down || at > out.alpha_down->at))
            out.alpha_down = Crossing{at, *r};
    }
}

} // namespace

BreakEven break_even(const ObjectiveWeights &weights, const DesignPoint &chosen,
                     const std::vector<DesignPoint> &designs) {
    BreakEven out;
    std::vector<const DesignPoint *> rivals;
    for (const auto &d : designs)
        if (d.configuration != chosen.configuration)
            rivals.push_back(&d);
    out.designs_compared = static_cast<long long>(rivals.size()) + 1;
    if (std::isinf(objective_at(weights, chosen).value))
        return out;
    scan_horizons(weights, chosen, rivals, out);
    alpha_crossings(weights, chosen, rivals, out);
    return out;
}

} // namespace envdesign::design
