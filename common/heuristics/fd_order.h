#pragma once
// An approximation of the fact and operator orders Fast Downward's translator would give
// a task.
//
// LM-cut's estimate depends on tie-breaking: which of several equally expensive
// preconditions becomes an operator's h^max supporter. FD breaks these ties by the order of
// its SAS+ variables and values (initial facts are queued in that order, preconditions and
// effects are listed in it). To keep our estimates, and so our expansion counts, close to
// FD's astar(lmcut()), RelaxedTask lists facts in the order FD's translator would choose:
// variables are the mutex groups (and single ungrouped facts), values sorted by name,
// groups sorted as FD's sort_groups does, and then reordered by the causal graph like
// FD's variable_order.py (strongly connected components in topological order, each
// component linearised greedily by minimum incoming weight, goal edges weighted high).
// Operators are ordered by name, as FD's translator sorts them. It is an approximation:
// FD's own mutex groups may differ from the grounder's.

#include "ground/ground_task.h"

#include <vector>

namespace envdesign::heuristics {

struct FdOrder {
    std::vector<int> fact_variable; // per fact: the position of its variable in FD's order
    std::vector<int> fact_rank;     // per fact: its position when sorted by (variable, value)
    std::vector<ground::OperatorId> operators; // the task's operators in FD's order
    // Facts true initially that no operator deletes: true in every reachable state. FD's
    // translator drops them (they are static once unreachable adders are gone), so they
    // never decide FD's ties: they rank after all other facts, and the successor order
    // ignores them.
    std::vector<bool> always_true;
};

FdOrder compute_fd_order(const ground::GroundTask &task);

} // namespace envdesign::heuristics
