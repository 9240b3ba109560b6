#pragma once
// Finds the operators applicable in a state.
//
// Every operator is filed under one of its preconditions, its key: the one most likely to
// be false, judged by the size of its mutex group (a fact of a group of n is one of n+1
// alternatives). A state then only looks at the operators filed under its true facts and
// checks their other preconditions on the state's bitset. Operators without preconditions
// are always applicable.
//
// Operators come out in the order of Fast Downward's successor generator (by their
// preconditions in FD's fact order, see heuristics/fd_order.h): with FIFO tie-breaking in
// the open list, this keeps expansion counts close to FD's.

#include "ground/ground_task.h"
#include "search/state_codec.h"

#include <vector>

namespace envdesign::search {

class SuccessorGenerator {
public:
    // Keeps no reference to `task`.
    explicit SuccessorGenerator(const ground::GroundTask &task);

    // Replaces `out` by the operators applicable in `state`, in FD's generation order.
    void applicable_operators(const UnpackedState &state,
                              std::vector<ground::OperatorId> &out) const;

private:
    std::vector<int> keyed_offsets_; // per fact: range in keyed_operators_
    std::vector<ground::OperatorId> keyed_operators_;
    std::vector<ground::OperatorId> unconditional_;
    std::vector<int> rest_offsets_; // per operator: its non-key preconditions
    std::vector<ground::FactId> rest_;
    std::vector<int> generation_rank_; // per operator: position in FD's order
};

} // namespace envdesign::search
