#pragma once
// The delete relaxation of a GroundTask in flat (CSR) arrays, shared by h^max and LM-cut.
//
// Propositions are the task's facts plus two artificial ones: ARTIFICIAL_PRECONDITION, true
// in every state and the only precondition of operators that have none (so every operator
// is triggered by some proposition), and ARTIFICIAL_GOAL, the single effect of an extra
// zero-cost goal operator whose preconditions are the task's goal facts. Relaxed operator
// i < num_task_operators is task operator i (its add effects only); the last one is the
// goal operator. This mirrors Fast Downward's LM-cut construction.

#include "ground/ground_task.h"

#include <span>
#include <vector>

namespace envdesign::heuristics {

class RelaxedTask {
public:
    explicit RelaxedTask(const ground::GroundTask &task);

    int num_propositions() const { return num_facts_ + 2; }
    int num_operators() const { return num_task_operators_ + 1; }
    int num_task_operators() const { return num_task_operators_; }
    int artificial_precondition() const { return num_facts_; }
    int artificial_goal() const { return num_facts_ + 1; }
    int goal_operator() const { return num_task_operators_; }

    int cost(int op) const { return costs_[op]; }
    std::span<const int> preconditions(int op) const { return slice(pre_, op); }
    std::span<const int> effects(int op) const { return slice(eff_, op); }
    std::span<const int> precondition_of(int prop) const { return slice(pre_of_, prop); }
    std::span<const int> effect_of(int prop) const { return slice(eff_of_, prop); }

private:
    // A list of lists: entries of list i are items[offsets[i] .. offsets[i+1]).
    struct Csr {
        std::vector<int> offsets{0};
        std::vector<int> items;
    };
    static std::span<const int> slice(const Csr &csr, int i) {
        return {csr.items.data() + csr.offsets[i], csr.items.data() + csr.offsets[i + 1]};
    }
    static Csr invert(const Csr &lists, int num_targets);

    int num_facts_;
    int num_task_operators_;
    std::vector<int> costs_;
    Csr pre_;
    Csr eff_;
    Csr pre_of_;
    Csr eff_of_;
};

}  // namespace envdesign::heuristics
