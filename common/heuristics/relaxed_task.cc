#include "heuristics/relaxed_task.h"

namespace envdesign::heuristics {

RelaxedTask::RelaxedTask(const ground::GroundTask &task)
    : num_facts_(task.num_facts()), num_task_operators_(task.num_operators()) {
    costs_.reserve(num_operators());
    auto add_operator = [&](const std::vector<ground::FactId> &pre,
                            const std::vector<ground::FactId> &eff, int cost) {
        if (pre.empty())
            pre_.items.push_back(artificial_precondition());
        else
            pre_.items.insert(pre_.items.end(), pre.begin(), pre.end());
        pre_.offsets.push_back(static_cast<int>(pre_.items.size()));
        eff_.items.insert(eff_.items.end(), eff.begin(), eff.end());
        eff_.offsets.push_back(static_cast<int>(eff_.items.size()));
        costs_.push_back(cost);
    };
    for (const ground::GroundOperator &op : task.operators)
        add_operator(op.pre, op.add, op.cost);
    add_operator(task.goal, {artificial_goal()}, 0);
    pre_of_ = invert(pre_, num_propositions());
    eff_of_ = invert(eff_, num_propositions());
}

// Operators appear in each proposition's list in increasing id order, as in FD, because
// the achiever and trigger order decides h^max supporter ties.
RelaxedTask::Csr RelaxedTask::invert(const Csr &lists, int num_targets) {
    Csr result;
    std::vector<int> counts(num_targets + 1, 0);
    for (int item : lists.items)
        ++counts[item + 1];
    for (int i = 0; i < num_targets; ++i)
        counts[i + 1] += counts[i];
    result.offsets = counts;
    result.items.resize(lists.items.size());
    int num_lists = static_cast<int>(lists.offsets.size()) - 1;
    for (int list = 0; list < num_lists; ++list)
        for (int k = lists.offsets[list]; k < lists.offsets[list + 1]; ++k)
            result.items[counts[lists.items[k]]++] = list;
    return result;
}

}  // namespace envdesign::heuristics
