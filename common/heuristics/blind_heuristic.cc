#include "heuristics/blind_heuristic.h"

#include <algorithm>

namespace envdesign::heuristics {

BlindHeuristic::BlindHeuristic(const ground::GroundTask &task) : goal_(task.goal) {
    // With no operators every non-goal state is a dead end anyway; 0 keeps h admissible.
    if (!task.operators.empty()) {
        min_operator_cost_ = task.operators.front().cost;
        for (const ground::GroundOperator &op : task.operators)
            min_operator_cost_ = std::min(min_operator_cost_, static_cast<int>(op.cost));
    }
}

int BlindHeuristic::compute(const StateView &state) {
    for (ground::FactId fact : goal_)
        if (!state.holds(fact))
            return min_operator_cost_;
    return 0;
}

} // namespace envdesign::heuristics
