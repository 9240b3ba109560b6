#include "search/inherited_lmcut.h"

#include <algorithm>

namespace envdesign::search {

InheritedLmCut::InheritedLmCut(const ground::GroundTask &task)
    : lmcut_(task), spent_(task.num_operators(), 0) {}

bool InheritedLmCut::contains(const Cut &cut, ground::OperatorId op) const {
    return std::binary_search(operators_.begin() + cut.begin, operators_.begin() + cut.end, op);
}

int InheritedLmCut::residual(const UnpackedState &state, std::vector<int> &found) {
    return lmcut_.compute_residual(state.facts, spent_,
                                   [&](std::span<const ground::OperatorId> ops, int cost) {
                                       std::size_t begin = operators_.size();
                                       operators_.insert(operators_.end(), ops.begin(), ops.end());
                                       std::sort(operators_.begin() + begin, operators_.end());
                                       found.push_back(static_cast<int>(cuts_.size()));
                                       cuts_.push_back({cost, begin, operators_.size()});
                                   });
}

void InheritedLmCut::spend(const std::vector<int> &cuts, int sign) {
    for (int c : cuts)
        for (std::size_t k = cuts_[c].begin; k < cuts_[c].end; ++k)
            spent_[operators_[k]] += sign * cuts_[c].cost;
}

void InheritedLmCut::keep(StateID id, std::vector<int> cuts) {
    if (id >= state_cuts_.size())
        state_cuts_.resize(id + 1);
    cut_entries_ += cuts.capacity();
    state_cuts_[id] = std::move(cuts);
}

int InheritedLmCut::initial(StateID id, const UnpackedState &state) {
    std::vector<int> found;
    int h = residual(state, found); // nothing spent yet: plain LM-cut
    if (h != heuristics::DEAD_END)
        keep(id, std::move(found));
    return h;
}

int InheritedLmCut::inherited(StateID parent, ground::OperatorId op) const {
    if (parent >= state_cuts_.size())
        return 0;
    int sum = 0;
    for (int c : state_cuts_[parent])
        if (!contains(cuts_[c], op))
            sum += cuts_[c].cost;
    return sum;
}

int InheritedLmCut::successor(StateID child, const UnpackedState &state, StateID parent,
                              ground::OperatorId op) {
    std::vector<int> kept;
    int sum = 0;
    if (parent < state_cuts_.size())
        for (int c : state_cuts_[parent])
            if (!contains(cuts_[c], op)) {
                kept.push_back(c);
                sum += cuts_[c].cost;
            }
    spend(kept, 1);
    std::vector<int> found;
    int h = residual(state, found);
    spend(kept, -1); // spent_ is all zero between calls
    if (h == heuristics::DEAD_END)
        return h; // never expanded: nothing to pass on
    kept.insert(kept.end(), found.begin(), found.end());
    keep(child, std::move(kept));
    return h + sum;
}

void InheritedLmCut::expanded(StateID parent) {
    if (parent >= state_cuts_.size())
        return;
    cut_entries_ -= state_cuts_[parent].capacity();
    std::vector<int>().swap(state_cuts_[parent]);
}

std::size_t InheritedLmCut::memory_bytes() const {
    return cuts_.capacity() * sizeof(Cut) + operators_.capacity() * sizeof(ground::OperatorId) +
           state_cuts_.capacity() * sizeof(std::vector<int>) + cut_entries_ * sizeof(int) +
           spent_.capacity() * sizeof(int);
}

std::vector<std::pair<int, std::vector<ground::OperatorId>>>
InheritedLmCut::cuts_of(StateID id) const {
    std::vector<std::pair<int, std::vector<ground::OperatorId>>> out;
    if (id < state_cuts_.size())
        for (int c : state_cuts_[id])
            out.push_back(
                {cuts_[c].cost,
                 {operators_.begin() + cuts_[c].begin, operators_.begin() + cuts_[c].end}});
    return out;
}

} // namespace envdesign::search
