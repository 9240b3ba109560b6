#pragma once
// The LM-cut landmark computation (Helmert & Domshlak, ICAPS 2009), separate from the
// heuristic adapter so that the design search can reuse the cuts.
//
// Each round computes h^max with a supporter (a most expensive precondition) per operator,
// marks the goal zone (propositions from which the artificial goal is reachable through
// zero-cost supporter edges), and cuts the operators that lead from the part of the
// justification graph reachable from the state (before the goal zone) into the goal zone.
// The cut is a disjunctive action landmark; its cost is the minimum operator cost in it,
// which is subtracted from its operators before h^max is repaired incrementally. The sum of
// cut costs is the LM-cut estimate.
//
// Implementation follows Fast Downward's: FD's adaptive bucket queue and supporter
// tie-breaking (the last precondition popped; on repair, the first of maximum cost), FD's
// fact and operator order (relaxed_task.h), and the incremental h^max update after each
// cut, so estimates equal FD's. For speed, each proposition keeps a bitmask over its
// precondition_of list marking the operators it supports: both the second exploration
// and the repair visit exactly those operators, in FD's order, without scanning the rest.
// All scratch memory is kept between calls.
//
// Example:
//   LmCutLandmarks lmcut(task);
//   int h = lmcut.compute(state_facts, [&](std::span<const ground::OperatorId> cut, int cost) {
//       ...  // one disjunctive action landmark
//   });

#include "ground/ground_task.h"
#include "heuristics/adaptive_queue.h"
#include "heuristics/relaxed_task.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace envdesign::heuristics {

class LmCutLandmarks {
public:
    // Receives one cut: the task operators in it (no duplicates) and its cost (> 0). The
    // span is valid only during the call.
    using CutCallback = std::function<void(std::span<const ground::OperatorId>, int)>;

    // Keeps no reference to `task`.
    explicit LmCutLandmarks(const ground::GroundTask &task);

    // `facts`: the true facts of the state (any order, no duplicates). Returns the sum of
    // the cut costs (0 iff h^max is 0), or DEAD_END (no cuts reported) if the goal is
    // unreachable in the delete relaxation. Not thread-safe.
    int compute(std::span<const ground::FactId> facts, const CutCallback &on_cut = {});

    // As compute(), with task operator o costing cost(o) - spent[o] (spent is indexed by
    // task operator, 0 <= spent[o] <= cost(o)): the rest of a cost partition whose other
    // part the caller holds as landmarks of its own (incremental LM-cut, Pommerening and
    // Helmert 2013). The sum of both parts is an admissible estimate.
    int compute_residual(std::span<const ground::FactId> facts, std::span<const int> spent,
                         const CutCallback &on_cut = {});

private:
    static constexpr int UNREACHED = 0x7fffffff;

    struct OperatorData {
        int cost;           // remaining cost in this computation
        int unsatisfied;    // preconditions not yet reached (first exploration)
        int supporter;      // h^max supporter proposition, -1 while unreached
        int supporter_cost; // h^max cost of the supporter
        int supporter_bit;  // this operator's bit in the supporter's mask
    };

    void first_exploration(std::span<const ground::FactId> facts);
    void first_exploration_incremental();
    void mark_goal_plateau();
    void second_exploration(); // from ranked_facts_, set by first_exploration
    void next_zone_stamps();
    void update_supporter(int op);
    void set_supporter(int op, int prop, int bit);
    void enqueue_if_necessary(int prop, int cost) {
        if (prop_cost_[prop] > cost) {
            prop_cost_[prop] = cost;
            queue_.push(cost, prop);
        }
    }
    bool in_goal_zone(int prop) const { return zone_[prop] == goal_zone_stamp_; }
    // Calls visit(op) for each operator `prop` supports, in increasing id order. Bits are
    // read a word at a time, so visit may move the current operator to another supporter.
    template <class Visit> void for_each_supported(int prop, Visit visit);

    RelaxedTask relaxed_;
    std::vector<OperatorData> ops_;
    std::vector<int> num_preconditions_;
    std::vector<int> prop_cost_; // h^max cost, UNREACHED if not reached
    // One per precondition_of entry (same flat index): the operator and its effects, so
    // the hot loops reach an operator's first effect with one load instead of three.
    struct Trigger {
        int op;
        int num_effects;
        int first_effect;  // valid if num_effects > 0
        int effects_begin; // into relaxed_.effect_items()
    };
    std::vector<Trigger> triggers_;
    // precondition_bit_[precondition_offset(op) + i]: op's index in the precondition_of
    // list of its i-th precondition.
    std::vector<int> precondition_bit_;
    // Supporter masks: proposition p owns words [mask_offset_[p], mask_offset_[p + 1]);
    // bit k set iff precondition_of(p)[k] has p as its supporter.
    std::vector<int> mask_offset_;
    std::vector<std::uint64_t> masks_;
    // Zone marks without a per-round reset: a proposition is in the goal zone iff its
    // stamp equals goal_zone_stamp_, before it iff the stamp is goal_zone_stamp_ + 1.
    std::vector<std::uint32_t> zone_;
    std::uint32_t goal_zone_stamp_ = 0;
    AdaptiveQueue queue_;
    std::vector<int> stack_;
    std::vector<int> cut_;
    std::vector<ground::FactId> ranked_facts_; // the state's facts in FD's order
    std::vector<ground::OperatorId> landmark_;
    std::span<const int> spent_; // of compute_residual, for first_exploration
};

} // namespace envdesign::heuristics
