#include "search/successor_generator.h"

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

}  // namespace

SuccessorGenerator::SuccessorGenerator(const ground::GroundTask &task) {
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
    std::sort(out.begin(), out.end());
}

}  // namespace envdesign::search
