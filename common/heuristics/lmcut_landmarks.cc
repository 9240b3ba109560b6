#include "heuristics/lmcut_landmarks.h"

#include "heuristics/heuristic.h"

#include <algorithm>
#include <bit>
#include <cassert>

namespace envdesign::heuristics {

LmCutLandmarks::LmCutLandmarks(const ground::GroundTask &task)
    : relaxed_(task), ops_(relaxed_.num_operators()), num_preconditions_(relaxed_.num_operators()),
      prop_cost_(relaxed_.num_propositions()),
      precondition_bit_(relaxed_.num_precondition_entries()),
      zone_(relaxed_.num_propositions(), 0) {
    for (int op = 0; op < relaxed_.num_operators(); ++op)
        num_preconditions_[op] = static_cast<int>(relaxed_.preconditions(op).size());
    // One pass over the precondition_of lists; precondition lists are short, so finding
    // the precondition's index is cheap even when a proposition has many users.
    for (int prop = 0; prop < relaxed_.num_propositions(); ++prop) {
        std::span<const int> users = relaxed_.precondition_of(prop);
        for (int k = 0; k < static_cast<int>(users.size()); ++k) {
            std::span<const int> pre = relaxed_.preconditions(users[k]);
            int i = static_cast<int>(std::find(pre.begin(), pre.end(), prop) - pre.begin());
            precondition_bit_[relaxed_.precondition_offset(users[k]) + i] = k;
        }
    }
    const int *users = relaxed_.precondition_of_items();
    const int *eff_offsets = relaxed_.effect_offsets();
    for (int i = 0; i < relaxed_.num_precondition_entries(); ++i) {
        int op = users[i];
        int begin = eff_offsets[op], end = eff_offsets[op + 1];
        triggers_.push_back(
            {op, end - begin, begin < end ? relaxed_.effect_items()[begin] : -1, begin});
    }
    mask_offset_.push_back(0);
    for (int prop = 0; prop < relaxed_.num_propositions(); ++prop) {
        int users = static_cast<int>(relaxed_.precondition_of(prop).size());
        mask_offset_.push_back(mask_offset_.back() + (users + 63) / 64);
    }
    masks_.assign(mask_offset_.back(), 0);
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

int LmCutLandmarks::compute_residual(std::span<const ground::FactId> facts,
                                     std::span<const int> spent, const CutCallback &on_cut) {
    spent_ = spent;
    int h = 0;
    try {
        h = compute(facts, on_cut);
    } catch (...) {
        spent_ = {};
        throw;
    }
    spent_ = {};
    return h;
}

template <class Visit> void LmCutLandmarks::for_each_supported(int prop, Visit visit) {
    const std::span<const int> users = relaxed_.precondition_of(prop);
    for (int w = mask_offset_[prop]; w < mask_offset_[prop + 1]; ++w) {
        const int base = (w - mask_offset_[prop]) * 64;
        for (std::uint64_t word = masks_[w]; word != 0; word &= word - 1)
            visit(users[base + std::countr_zero(word)]);
    }
}

void LmCutLandmarks::first_exploration(std::span<const ground::FactId> facts) {
    queue_.clear();
    std::fill(prop_cost_.begin(), prop_cost_.end(), UNREACHED);
    std::fill(masks_.begin(), masks_.end(), 0);
    const int num_ops = relaxed_.num_operators();
    for (int op = 0; op < num_ops; ++op)
        ops_[op] = {relaxed_.cost(op), num_preconditions_[op], -1, UNREACHED, 0};
    if (!spent_.empty()) // the goal operator (the last) costs 0 and is never spent
        for (int op = 0; op < relaxed_.num_task_operators(); ++op)
            ops_[op].cost -= spent_[relaxed_.task_operator(op)];
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
        std::span<const int> users = relaxed_.precondition_of(prop);
        for (int k = 0; k < static_cast<int>(users.size()); ++k) {
            const int op = users[k];
            OperatorData &data = ops_[op];
            if (--data.unsatisfied == 0) {
                // The last precondition popped has the maximum cost: the supporter.
                set_supporter(op, prop, k);
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
        // Plain variables, not a structured binding: clang 14 cannot capture those in a lambda.
        auto popped = queue_.pop();
        int cost = popped.first;
        auto prop = popped.second;
        if (cost > prop_cost_[prop])
            continue;
        for_each_supported(prop, [&](int op) {
            OperatorData &data = ops_[op];
            if (data.supporter_cost <= cost)
                return;
            int old_cost = data.supporter_cost;
            update_supporter(op);
            if (data.supporter_cost != old_cost) {
                int target = data.supporter_cost + data.cost;
                for (int effect : relaxed_.effects(op))
                    enqueue_if_necessary(effect, target);
            }
        });
    }
}

void LmCutLandmarks::update_supporter(int op) {
    OperatorData &data = ops_[op];
    std::span<const int> pre = relaxed_.preconditions(op);
    int best = -1;
    int best_cost = prop_cost_[data.supporter];
    for (int i = 0; i < static_cast<int>(pre.size()); ++i) {
        if (prop_cost_[pre[i]] > best_cost) {
            best = i;
            best_cost = prop_cost_[pre[i]];
        }
    }
    if (best >= 0)
        set_supporter(op, pre[best], precondition_bit_[relaxed_.precondition_offset(op) + best]);
    data.supporter_cost = best_cost;
}

void LmCutLandmarks::set_supporter(int op, int prop, int bit) {
    OperatorData &data = ops_[op];
    if (data.supporter >= 0) {
        int old = mask_offset_[data.supporter] + data.supporter_bit / 64;
        masks_[old] &= ~(std::uint64_t(1) << (data.supporter_bit % 64));
    }
    data.supporter = prop;
    data.supporter_bit = bit;
    masks_[mask_offset_[prop] + bit / 64] |= std::uint64_t(1) << (bit % 64);
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

void LmCutLandmarks::second_exploration() {
    // Raw pointers to locals: stores to the stack and the zone marks could otherwise alias
    // every member the loop reads, forcing reloads.
    const std::uint32_t before = goal_zone_stamp_ + 1;
    const std::uint32_t goal_zone = goal_zone_stamp_;
    std::uint32_t *const zone = zone_.data();
    const int *const eff_items = relaxed_.effect_items();
    const int *const users_offsets = relaxed_.precondition_of_offsets();
    const Trigger *const triggers = triggers_.data();
    const int *const mask_offset = mask_offset_.data();
    const std::uint64_t *const masks = masks_.data();
    stack_.resize(relaxed_.num_propositions() + 1);
    int *const stack = stack_.data();
    int top = 0;
    cut_.resize(relaxed_.num_operators());
    int *const cut = cut_.data();
    int cut_size = 0;
    const int artificial = relaxed_.artificial_precondition();
    zone[artificial] = before;
    stack[top++] = artificial;
    // FD has no always-true facts; what they support, FD's artificial precondition would,
    // and that sits at the bottom of FD's stack. So they go below the other facts.
    const int first_always_true = relaxed_.first_always_true_rank();
    auto regular_end =
        std::partition_point(ranked_facts_.begin(), ranked_facts_.end(), [&](ground::FactId f) {
            return relaxed_.fact_rank(f) < first_always_true;
        });
    for (auto it = regular_end; it != ranked_facts_.end(); ++it) {
        zone[*it] = before;
        stack[top++] = *it;
    }
    for (auto it = ranked_facts_.begin(); it != regular_end; ++it) {
        zone[*it] = before;
        stack[top++] = *it;
    }
    while (top > 0) {
        const int prop = stack[--top];
        const Trigger *entries = triggers + users_offsets[prop];
        for (int w = mask_offset[prop]; w < mask_offset[prop + 1]; ++w, entries += 64) {
            for (std::uint64_t word = masks[w]; word != 0; word &= word - 1) {
                const Trigger &t = entries[std::countr_zero(word)];
                if (t.num_effects == 1) { // the common case, without the loops below
                    const std::uint32_t z = zone[t.first_effect];
                    if (z == goal_zone) {
                        cut[cut_size++] = t.op;
                    } else if (z != before) {
                        zone[t.first_effect] = before;
                        stack[top++] = t.first_effect;
                    }
                    continue;
                }
                const int *eff = eff_items + t.effects_begin;
                const int *eff_end = eff + t.num_effects;
                bool into_goal_zone = false;
                for (const int *e = eff; e != eff_end; ++e)
                    into_goal_zone |= zone[*e] == goal_zone;
                if (into_goal_zone) {
                    cut[cut_size++] = t.op;
                    continue;
                }
                for (const int *e = eff; e != eff_end; ++e) {
                    if (zone[*e] != before) {
                        zone[*e] = before;
                        stack[top++] = *e;
                    }
                }
            }
        }
    }
    cut_.resize(cut_size);
    assert(std::all_of(cut_.begin(), cut_.end(), [&](int op) { return ops_[op].cost > 0; }));
}

} // namespace envdesign::heuristics
