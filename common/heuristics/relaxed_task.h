#pragma once
// The delete relaxation of a GroundTask in flat (CSR) arrays, shared by h^max and LM-cut.
//
// Propositions are the task's facts plus two artificial ones: ARTIFICIAL_PRECONDITION, true
// in every state and the only precondition of operators that have none (so every operator
// is triggered by some proposition), and ARTIFICIAL_GOAL, the single effect of an extra
// zero-cost goal operator whose preconditions are the task's goal facts. Relaxed operators
// i < num_task_operators are the task's operators (their add effects only) in FD's order,
// task_operator(i) maps back; the last one is the goal operator. This mirrors Fast
// Downward's LM-cut construction.
//
// Preconditions, effects and the goal are listed in the order FD's translator would give
// them (fd_order.h): first the preconditions on variables the operator does not
// change, then those it changes, each by variable. fact_rank() ranks facts the same way
// for queueing a state's facts. These orders only decide ties, as in FD. Facts true in
// every reachable state (FdOrder::always_true), which FD's translator drops, come last in
// these orders, so that they never win a tie FD would not see.

#include "ground/ground_task.h"
#include "heuristics/fd_order.h"

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
    ground::OperatorId task_operator(int op) const { return task_operators_[op]; }
    // Position of each fact in FD's (variable, value) order.
    int fact_rank(ground::FactId fact) const { return fact_rank_[fact]; }
    // Facts of rank >= this are always true (FdOrder::always_true).
    int first_always_true_rank() const { return first_always_true_rank_; }
    std::span<const int> preconditions(int op) const { return slice(pre_, op); }
    std::span<const int> effects(int op) const { return slice(eff_, op); }
    std::span<const int> precondition_of(int prop) const { return slice(pre_of_, prop); }
    std::span<const int> effect_of(int prop) const { return slice(eff_of_, prop); }
    // Where an operator's preconditions (a proposition's precondition_of list) start in
    // one flat array of all of them: lets callers keep parallel per-entry data.
    int precondition_offset(int op) const { return pre_.offsets[op]; }
    int precondition_of_offset(int prop) const { return pre_of_.offsets[prop]; }
    int num_precondition_entries() const { return static_cast<int>(pre_.items.size()); }
    // The flat arrays behind effects() and precondition_of(), for hot loops.
    const int *effect_offsets() const { return eff_.offsets.data(); }
    const int *effect_items() const { return eff_.items.data(); }
    const int *precondition_of_offsets() const { return pre_of_.offsets.data(); }
    const int *precondition_of_items() const { return pre_of_.items.data(); }

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
    std::vector<int> fact_rank_;
    int first_always_true_rank_ = 0;
    std::vector<ground::OperatorId> task_operators_;
    Csr pre_;
    Csr eff_;
    Csr pre_of_;
    Csr eff_of_;
};

} // namespace envdesign::heuristics
