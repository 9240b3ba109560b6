#pragma once
// Small hand-built tasks and a helper to evaluate a heuristic on a set of facts.

#include "ground/ground_task.h"
#include "heuristics/heuristic.h"

#include <algorithm>
#include <string>
#include <vector>

namespace envdesign::heuristics::testing {

inline ground::GroundOperator op(std::vector<ground::FactId> pre, std::vector<ground::FactId> add,
                                 int cost, std::vector<ground::FactId> del = {}) {
    static int counter = 0;
    return {"(op" + std::to_string(counter++) + ")", pre, add, del, cost, 0};
}

inline ground::GroundTask make_task(int num_facts, std::vector<ground::GroundOperator> ops,
                                    std::vector<ground::FactId> init,
                                    std::vector<ground::FactId> goal) {
    ground::GroundTask task;
    for (int f = 0; f < num_facts; ++f)
        task.fact_names.push_back("(f" + std::to_string(f) + ")");
    task.operators = std::move(ops);
    task.initial_state = std::move(init);
    task.goal = std::move(goal);
    task.has_action_costs = true;
    return task;
}

// Evaluates `h` on the state whose true facts are `facts`.
inline int evaluate(Heuristic &h, const ground::GroundTask &task,
                    std::vector<ground::FactId> facts) {
    std::sort(facts.begin(), facts.end());
    std::vector<std::uint64_t> bits(bitset_words(task), 0);
    for (ground::FactId f : facts)
        bits[f / 64] |= std::uint64_t(1) << (f % 64);
    return h.compute(StateView(facts, bits));
}

} // namespace envdesign::heuristics::testing
