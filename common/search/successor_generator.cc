#include "search/successor_generator.h"

#include "heuristics/fd_order.h"

#include <algorithm>

namespace envdesign::search {
namespace {

std::vector<int> mutex_group_sizes(const ground::GroundTask &task) {
    std::vector<int> size(task.num_facts(), 1);
    for (const auto &group : task.mutex_groups)
        for (ground::FactId fact : group)
            size[fact] = static_cast<int>(group.size());
    return size;
}

// FD's generator is a decision tree over operators sorted by their (variable, value)
// preconditions, so it yields applicable operators in that lexicographic order; operators
// with equal preconditions come in FD's operator order.
std::vector<int> fd_generation_ranks(const ground::GroundTask &task) {
    heuristics::FdOrder order = heuristics::compute_fd_order(task);
    std::vector<std::vector<int>> keys(task.num_operators());
    for (ground::OperatorId op = 0; op < task.num_operators(); ++op) {
        for (ground::FactId fact : task.operators[op].pre)
            if (!order.always_true[fact])
                keys[op].push_back(order.fact_rank[fact]);
        std::sort(keys[op].begin(), keys[op].end());
    }
    std::vector<ground::OperatorId> ops = order.operators;
    std::stable_sort(ops.begin(), ops.end(),
                     [&](ground::OperatorId a, ground::OperatorId b) { return keys[a] < keys[b]; });
    std::vector<int> rank(task.num_operators());
    for (int i = 0; i < task.num_operators(); ++i)
        rank[ops[i]] = i;
    return rank;
}

} // namespace

SuccessorGenerator::SuccessorGenerator(const ground::GroundTask &task)
    : generation_rank_(fd_generation_ranks(task)) {
    std::vector<int> group_size = mutex_group_sizes(task);
    std::vector<ground::FactId> key(task.num_operators(), -1);
    std::vector<int> count(task.num_facts() + 1, 0);
    rest_offsets_.push_back(0);
    for (ground::OperatorId op = 0; op < task.num_operators(); ++op) {
        const std::vector<ground::FactId> &pre = task.operators[op].pre;
        if (pre.empty()) {
            unconditional_.push_back(op);
        } else {
            key[op] = *std::max_element(pre.begin(), pre.end(), [&](auto a, auto b) {
                return group_size[a] < group_size[b];
            });
            ++count[key[op] + 1];
        }
        for (ground::FactId fact : pre)
            if (fact != key[op])
                rest_.push_back(fact);
        rest_offsets_.push_back(static_cast<int>(rest_.size()));
    }
    for (int fact = 0; fact < task.num_facts(); ++fact)
        count[fact + 1] += count[fact];
    keyed_offsets_ = count;
    keyed_operators_.resize(count.back());
    for (ground::OperatorId op = 0; op < task.num_operators(); ++op)
        if (key[op] >= 0)
            keyed_operators_[count[key[op]]++] = op;
}

void SuccessorGenerator::applicable_operators(const UnpackedState &state,
                                              std::vector<ground::OperatorId> &out) const {
    out.assign(unconditional_.begin(), unconditional_.end());
    for (ground::FactId fact : state.facts) {
        for (int k = keyed_offsets_[fact]; k < keyed_offsets_[fact + 1]; ++k) {
            ground::OperatorId op = keyed_operators_[k];
            bool applicable = true;
            for (int r = rest_offsets_[op]; r < rest_offsets_[op + 1] && applicable; ++r)
                applicable = state.holds(rest_[r]);
            if (applicable)
                out.push_back(op);
        }
    }
    std::sort(out.begin(), out.end(), [&](ground::OperatorId a, ground::OperatorId b) {
        return generation_rank_[a] < generation_rank_[b];
    });
}

} // namespace envdesign::search
