#pragma once
// Overview: the ground task, the boundary between parsing and search.
//
// A GroundTask is a STRIPS task over integer ids: facts 0..num_facts-1, operators with
// precondition, add and delete lists, an initial state and a goal. It holds no PDDL; names
// are kept only to print plans. Everything downstream of grounding (search/, heuristics/,
// design/) sees only this type, the way Fast Downward's search sees only the translator's
// SAS+ output.
//
// Conventions the grounder guarantees (and search code may rely on):
//   - every list of FactIds is sorted and free of duplicates;
//   - an operator never has a fact in both add and del (add wins, PDDL semantics);
//   - negative preconditions and negative goals are compiled away into complementary
//     facts "(not (p ...))" that operators keep in sync, so the task is pure STRIPS;
//   - static facts are gone and every operator is relaxed-reachable from the initial state;
//   - mutex_groups are disjoint sets of facts of which at most one is true in any reachable
//     state; the state packer stores a group in ceil(log2(|group|+1)) bits.
//
// Example: a task with facts {at-a, at-b} and one operator move-a-b:
//   GroundTask t;
//   t.fact_names = {"(at a)", "(at b)"};
//   t.operators.push_back({"(move a b)", {0}, {1}, {0}, 1, 0});
//   t.initial_state = {0}; t.goal = {1};

#include <cstdint>
#include <string>
#include <vector>

namespace envdesign::ground {

using FactId = std::int32_t;
using OperatorId = std::int32_t;
using Cost = std::int32_t;

struct GroundOperator {
    std::string name;        // "(move a b)", lower case, for plan output only
    std::vector<FactId> pre; // facts that must be true
    std::vector<FactId> add; // facts made true
    std::vector<FactId> del; // facts made false
    Cost cost = 1;           // primary cost, >= 0
    Cost secondary_cost = 0; // tie-breaker among plans of equal primary cost, >= 0
};

struct GroundTask {
    std::vector<std::string> fact_names; // index = FactId
    std::vector<GroundOperator> operators;
    std::vector<FactId> initial_state; // the facts true initially
    std::vector<FactId> goal;          // the facts that must hold at the end
    std::vector<std::vector<FactId>> mutex_groups;
    bool has_action_costs = false; // false: every cost is 1 ("unit cost" in plan output)

    int num_facts() const { return static_cast<int>(fact_names.size()); }
    int num_operators() const { return static_cast<int>(operators.size()); }
};

} // namespace envdesign::ground
