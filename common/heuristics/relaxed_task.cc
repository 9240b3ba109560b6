#include "heuristics/relaxed_task.h"

#include <algorithm>
#include <tuple>

namespace envdesign::heuristics {
namespace {

// FD lists prevail conditions (on variables the operator leaves alone) before the
// preconditions of its effects, each group sorted by variable.
std::vector<ground::FactId> fd_precondition_order(const ground::GroundOperator &op,
                                                  const FdOrder &order) {
    std::vector<int> changed;
    for (ground::FactId f : op.add)
        if (!std::binary_search(op.pre.begin(), op.pre.end(), f))
            changed.push_back(order.fact_variable[f]);
    for (ground::FactId f : op.del)
        changed.push_back(order.fact_variable[f]);
    auto is_changed = [&](ground::FactId f) {
        return std::find(changed.begin(), changed.end(), order.fact_variable[f]) != changed.end();
    };
    std::vector<ground::FactId> pre = op.pre;
    std::stable_sort(pre.begin(), pre.end(), [&](ground::FactId a, ground::FactId b) {
        return std::tuple(order.always_true[a], is_changed(a), order.fact_rank[a]) <
               std::tuple(order.always_true[b], is_changed(b), order.fact_rank[b]);
    });
    return pre;
}

std::vector<ground::FactId> by_rank(std::vector<ground::FactId> facts, const FdOrder &order) {
    std::sort(facts.begin(), facts.end(), [&](ground::FactId a, ground::FactId b) {
        return order.fact_rank[a] < order.fact_rank[b];
    });
    return facts;
}

} // namespace

RelaxedTask::RelaxedTask(const ground::GroundTask &task)
    : num_facts_(task.num_facts()), num_task_operators_(task.num_operators()) {
    FdOrder order = compute_fd_order(task);
    fact_rank_ = order.fact_rank;
    first_always_true_rank_ =
        static_cast<int>(std::count(order.always_true.begin(), order.always_true.end(), false));
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
    task_operators_ = order.operators;
    for (ground::OperatorId id : task_operators_) {
        const ground::GroundOperator &op = task.operators[id];
        add_operator(fd_precondition_order(op, order), by_rank(op.add, order), op.cost);
    }
    add_operator(by_rank(task.goal, order), {artificial_goal()}, 0);
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

} // namespace envdesign::heuristics
