#include "heuristics/hmax_heuristic.h"

#include <algorithm>

namespace envdesign::heuristics {

HMaxHeuristic::HMaxHeuristic(const ground::GroundTask &task)
    : relaxed_(task), prop_cost_(relaxed_.num_propositions()),
      unsatisfied_(relaxed_.num_operators()), num_preconditions_(relaxed_.num_operators()) {
    for (int op = 0; op < relaxed_.num_operators(); ++op)
        num_preconditions_[op] = static_cast<int>(relaxed_.preconditions(op).size());
}

int HMaxHeuristic::compute(const StateView &state) {
    std::fill(prop_cost_.begin(), prop_cost_.end(), DEAD_END);
    std::copy(num_preconditions_.begin(), num_preconditions_.end(), unsatisfied_.begin());
    queue_.clear();
    for (ground::FactId fact : state.facts())
        enqueue_if_cheaper(fact, 0);
    enqueue_if_cheaper(relaxed_.artificial_precondition(), 0);
    const int goal = relaxed_.artificial_goal();
    while (!queue_.empty()) {
        auto [cost, prop] = queue_.pop();
        if (cost > prop_cost_[prop])
            continue; // a stale entry: the proposition was reached more cheaply since
        if (prop == goal)
            break; // later pops cannot lower the goal's cost
        for (int op : relaxed_.precondition_of(prop)) {
            // The last precondition to be popped is the most expensive one, so it fixes
            // the operator's h^max cost.
            if (--unsatisfied_[op] == 0) {
                int target = cost + relaxed_.cost(op);
                for (int effect : relaxed_.effects(op))
                    enqueue_if_cheaper(effect, target);
            }
        }
    }
    return prop_cost_[goal];
}

} // namespace envdesign::heuristics
