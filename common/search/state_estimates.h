#pragma once
// Estimates of h* a search asks for state by state, knowing the edge that reached each
// state: a plain heuristic ignores the edge (HeuristicEstimates), incremental LM-cut passes
// a parent's landmarks on to its successors (inherited_lmcut.h). The A* (astar_search.h)
// and the optimal-plan graph's forward search (design/behaviour/optimal_plan_graph.h) take
// either.
//
// Example:
//   auto h = heuristics::make_heuristic(heuristics::HeuristicKind::LMCUT, task);
//   HeuristicEstimates estimates(*h);
//   int h0 = estimates.initial(id, state);

#include "ground/ground_task.h"
#include "heuristics/heuristic.h"
#include "search/state_codec.h"
#include "search/state_registry.h"

#include <cstddef>

namespace envdesign::search {

class StateEstimates {
public:
    virtual ~StateEstimates();
    // h of the initial state, registered as `id`; DEAD_END if no goal is reachable.
    virtual int initial(StateID id, const UnpackedState &state) = 0;
    // A bound on h* of parent's successor by `op` that costs no search (0 if none known).
    // Called only while `parent` is being expanded.
    virtual int inherited(StateID parent, ground::OperatorId op) const = 0;
    // h of `child` (DEAD_END: none), first needed on the edge from `parent` by `op`. An
    // estimate may depend on that edge: a search computes each state's once.
    virtual int successor(StateID child, const UnpackedState &state, StateID parent,
                          ground::OperatorId op) = 0;
    // `parent` is expanded: what inherited() and successor() needed of it may go.
    virtual void expanded(StateID parent) = 0;
    virtual std::size_t memory_bytes() const = 0;
};

// A heuristic as estimates: no path-dependent part.
class HeuristicEstimates : public StateEstimates {
public:
    // Keeps a reference to `heuristic`, which must outlive it.
    explicit HeuristicEstimates(heuristics::Heuristic &heuristic) : heuristic_(heuristic) {}
    int initial(StateID, const UnpackedState &state) override { return of(state); }
    int inherited(StateID, ground::OperatorId) const override { return 0; }
    int successor(StateID, const UnpackedState &state, StateID, ground::OperatorId) override {
        return of(state);
    }
    void expanded(StateID) override {}
    std::size_t memory_bytes() const override { return 0; }

private:
    int of(const UnpackedState &state) {
        return heuristic_.compute(heuristics::StateView(state.facts, state.bits));
    }
    heuristics::Heuristic &heuristic_;
};

} // namespace envdesign::search
