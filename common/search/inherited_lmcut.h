#pragma once
// LM-cut estimates that a successor inherits from its parent (incremental LM-cut,
// Pommerening and Helmert, ICAPS 2013), for the A* (astar_search.h) and the optimal-plan
// graph's forward search (design/behaviour/optimal_plan_graph.h). Issue 24: LM-cut was
// nearly all of the design engine's time.
//
// LM-cut's cuts L of a state s, with costs c(L), are disjunctive action landmarks and a
// cost partition: every operator o has sum_{L containing o} c(L) <= cost(o). Every plan
// from s's successor t = s.a, with a in front, is a plan from s; so each cut of s without a
// is a landmark of t too, and those cuts, a subset of a partition, still bound h*(t) by
// their cost sum. The successor's estimate is that sum plus LM-cut on the costs they leave
// (LmCutLandmarks::compute_residual): the cuts of both parts form a cost partition again,
// so the estimate is admissible, and t passes its cuts on in turn. Only the residual is
// searched for: usually one or two cuts instead of one per unit of h. inherited() is the
// first part alone, which prunes some successors without any search.
//
// A state's cuts are kept from its estimate until it is expanded; a state expanded again
// (reopened) passes none on, and its successors get plain LM-cut.
//
// Example:
//   InheritedLmCut estimates(task);
//   AStarSearch search(task, estimates, limits);

#include "heuristics/lmcut_landmarks.h"
#include "search/state_estimates.h"

#include <cstddef>
#include <span>
#include <vector>

namespace envdesign::search {

class InheritedLmCut : public StateEstimates {
public:
    explicit InheritedLmCut(const ground::GroundTask &task);

    int initial(StateID id, const UnpackedState &state) override;
    int inherited(StateID parent, ground::OperatorId op) const override;
    int successor(StateID child, const UnpackedState &state, StateID parent,
                  ground::OperatorId op) override;
    void expanded(StateID parent) override;
    std::size_t memory_bytes() const override;

    // The cuts a state holds (until it is expanded), each as (cost, operators sorted).
    std::vector<std::pair<int, std::vector<ground::OperatorId>>> cuts_of(StateID id) const;

private:
    struct Cut {
        int cost;
        std::size_t begin; // its operators: operators_[begin .. end), ascending
        std::size_t end;
    };

    bool contains(const Cut &cut, ground::OperatorId op) const;
    // h of `state` on the costs spent_ leaves; its cuts are appended to `found`.
    int residual(const UnpackedState &state, std::vector<int> &found);
    // Adds (sign 1) or takes back (-1) the costs of `cuts` in spent_.
    void spend(const std::vector<int> &cuts, int sign);
    void keep(StateID id, std::vector<int> cuts);

    heuristics::LmCutLandmarks lmcut_;
    std::vector<Cut> cuts_;                     // every cut found, shared by the states
    std::vector<ground::OperatorId> operators_; // the cuts' operators
    std::vector<std::vector<int>> state_cuts_;  // per state: indices into cuts_
    std::vector<int> spent_;                    // per task operator, for one residual
    std::size_t cut_entries_ = 0;               // in state_cuts_, for memory_bytes()
};

} // namespace envdesign::search
