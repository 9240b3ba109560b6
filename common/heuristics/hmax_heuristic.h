#pragma once
// h^max (Bonet & Geffner 2001): the cost of the most expensive goal fact in the delete
// relaxation, where reaching a set of facts costs as much as its most expensive member.
// Computed by a generalised Dijkstra over the RelaxedTask with an integer AdaptiveQueue.

#include "heuristics/adaptive_queue.h"
#include "heuristics/heuristic.h"
#include "heuristics/relaxed_task.h"

#include <vector>

namespace envdesign::heuristics {

class HMaxHeuristic : public Heuristic {
public:
    explicit HMaxHeuristic(const ground::GroundTask &task);
    int compute(const StateView &state) override;

private:
    void enqueue_if_cheaper(int prop, int cost) {
        if (prop_cost_[prop] > cost) {
            prop_cost_[prop] = cost;
            queue_.push(cost, prop);
        }
    }

    RelaxedTask relaxed_;
    std::vector<int> prop_cost_;   // DEAD_END while unreached
    std::vector<int> unsatisfied_; // per operator: preconditions not yet reached
    std::vector<int> num_preconditions_;
    AdaptiveQueue queue_;
};

} // namespace envdesign::heuristics
