#include "heuristics/lmcut_landmarks.h"

#include "heuristics/heuristic.h"

#include <algorithm>
#include <cassert>

namespace envdesign::heuristics {

LmCutLandmarks::LmCutLandmarks(const ground::GroundTask &task)
    : relaxed_(task), ops_(relaxed_.num_operators()),
      num_preconditions_(relaxed_.num_operators()), prop_cost_(relaxed_.num_propositions()),
      zone_(relaxed_.num_propositions(), 0) {
    for (int op = 0; op < relaxed_.num_operators(); ++op)
        num_preconditions_[op] = static_cast<int>(relaxed_.preconditions(op).size());
}

int LmCutLandmarks::compute(std::span<const ground::FactId> facts, const CutCallback &on_cut) {
    first_exploration(facts);
    const int goal = relaxed_.artificial_goal();
    if (prop_cost_[goal] == UNREACHED)
        return DEAD_END;
    int total = 0;
    while (prop_cost_[goal] != 0) {
        next_zone_stamps();
        mark_goal_plateau();
        cut_.clear();
        second_exploration();
        assert(!cut_.empty());
        int cut_cost = UNREACHED;
        for (int op : cut_)
            cut_cost = std::min(cut_cost, ops_[op].cost);
        for (int op : cut_)
            ops_[op].cost -= cut_cost;
        total += cut_cost;
        if (on_cut) {
            // The goal operator costs 0, so it is never in a cut: every entry is a task op.
            landmark_.clear();
            for (int op : cut_)
                landmark_.push_back(relaxed_.task_operator(op));
            on_cut(landmark_, cut_cost);
        }
        first_exploration_incremental();
    }
    return total;
}

void LmCutLandmarks::first_exploration(std::span<const ground::FactId> facts) {
    queue_.clear();
    std::fill(prop_cost_.begin(), prop_cost_.end(), UNREACHED);
    const int num_ops = relaxed_.num_operators();
    for (int op = 0; op < num_ops; ++op)
        ops_[op] = {relaxed_.cost(op), num_preconditions_[op], -1, UNREACHED};
    // FD queues a state's facts in variable order; the bucket queue is LIFO, so this order
    // decides which of several cost-0 preconditions becomes the supporter.
    ranked_facts_.assign(facts.begin(), facts.end());
    std::sort(ranked_facts_.begin(), ranked_facts_.end(), [&](ground::FactId a, ground::FactId b) {
        return relaxed_.fact_rank(a) < relaxed_.fact_rank(b);
    });
    for (ground::FactId fact : ranked_facts_)
        enqueue_if_necessary(fact, 0);
    enqueue_if_necessary(relaxed_.artificial_precondition(), 0);
    while (!queue_.empty()) {
        auto [cost, prop] = queue_.pop();
        if (cost > prop_cost_[prop])
            continue;
        for (int op : relaxed_.precondition_of(prop)) {
            OperatorData &data = ops_[op];
            if (--data.unsatisfied == 0) {
                // The last precondition popped has the maximum cost: the supporter.
                data.supporter = prop;
                data.supporter_cost = cost;
                int target = cost + data.cost;
                for (int effect : relaxed_.effects(op))
                    enqueue_if_necessary(effect, target);
            }
        }
    }
}

// After a cut only its operators became cheaper, so only propositions whose supporting
// operators got cheaper need new costs; this repairs h^max from those operators outward.
void LmCutLandmarks::first_exploration_incremental() {
    assert(queue_.empty());
    // As in FD: counting the propositions as pushes keeps the queue bucket-based for
    // unit-cost tasks.
    queue_.add_virtual_pushes(relaxed_.num_propositions());
    for (int op : cut_) {
        int target = ops_[op].supporter_cost + ops_[op].cost;
        for (int effect : relaxed_.effects(op))
            enqueue_if_necessary(effect, target);
    }
    while (!queue_.empty()) {
        auto [cost, prop] = queue_.pop();
        if (cost > prop_cost_[prop])
            continue;
        for (int op : relaxed_.precondition_of(prop)) {
            OperatorData &data = ops_[op];
            if (data.supporter != prop || data.supporter_cost <= cost)
                continue;
            int old_cost = data.supporter_cost;
            update_supporter(op);
            if (data.supporter_cost != old_cost) {
                int target = data.supporter_cost + data.cost;
                for (int effect : relaxed_.effects(op))
                    enqueue_if_necessary(effect, target);
            }
        }
    }
}

void LmCutLandmarks::update_supporter(int op) {
    OperatorData &data = ops_[op];
    int best = data.supporter;
    for (int pre : relaxed_.preconditions(op))
        if (prop_cost_[pre] > prop_cost_[best])
            best = pre;
    data.supporter = best;
    data.supporter_cost = prop_cost_[best];
}

void LmCutLandmarks::next_zone_stamps() {
    if (goal_zone_stamp_ >= 0xfffffff0U) {
        std::fill(zone_.begin(), zone_.end(), 0);
        goal_zone_stamp_ = 0;
    }
    goal_zone_stamp_ += 2;
}

// The goal zone: the artificial goal and, recursively, the supporters of zero-cost
// achievers of goal-zone propositions. A zero-cost achiever may be unreached (supporter
// -1) in tasks that had zero-cost operators from the start; it contributes nothing.
void LmCutLandmarks::mark_goal_plateau() {
    stack_.clear();
    stack_.push_back(relaxed_.artificial_goal());
    while (!stack_.empty()) {
        int prop = stack_.back();
        stack_.pop_back();
        if (in_goal_zone(prop))
            continue;
        zone_[prop] = goal_zone_stamp_;
        for (int op : relaxed_.effect_of(prop)) {
            const OperatorData &data = ops_[op];
            if (data.cost == 0 && data.supporter >= 0 && !in_goal_zone(data.supporter))
                stack_.push_back(data.supporter);
        }
    }
}

// Walks the justification graph from the state; operators that lead into the goal zone
// form the cut, everything else they reach is before the goal zone.
void LmCutLandmarks::second_exploration() {
    const std::uint32_t before = goal_zone_stamp_ + 1;
    stack_.clear();
    const int artificial = relaxed_.artificial_precondition();
    zone_[artificial] = before;
    stack_.push_back(artificial);
    for (ground::FactId fact : ranked_facts_) {
        zone_[fact] = before;
        stack_.push_back(fact);
    }
    while (!stack_.empty()) {
        int prop = stack_.back();
        stack_.pop_back();
        for (int op : relaxed_.precondition_of(prop)) {
            if (ops_[op].supporter != prop)
                continue;
            std::span<const int> effects = relaxed_.effects(op);
            bool into_goal_zone = std::any_of(effects.begin(), effects.end(),
                                              [&](int e) { return in_goal_zone(e); });
            if (into_goal_zone) {
                assert(ops_[op].cost > 0);
                cut_.push_back(op);
                continue;
            }
            for (int effect : effects) {
                if (zone_[effect] != before) {
                    zone_[effect] = before;
                    stack_.push_back(effect);
                }
            }
        }
    }
}

}  // namespace envdesign::heuristics
