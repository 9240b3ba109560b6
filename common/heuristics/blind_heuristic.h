#pragma once
// The blind heuristic, as in Fast Downward: 0 in goal states, otherwise the cheapest
// operator cost (a trivially admissible bound, so A* with it is uniform-cost search).

#include "heuristics/heuristic.h"

#include <vector>

namespace envdesign::heuristics {

class BlindHeuristic : public Heuristic {
public:
    explicit BlindHeuristic(const ground::GroundTask &task);
    int compute(const StateView &state) override;

private:
    std::vector<ground::FactId> goal_;
    int min_operator_cost_ = 0;
};

} // namespace envdesign::heuristics
