#pragma once
// Mutex groups from monotonicity invariants ("at most one of these atoms is true"), found
// the way Fast Downward's translator finds them, but checked on ground operators: start
// from one predicate with at most one counted argument, and when an operator adds an atom
// of the group without deleting a required one, try adding the predicate it deletes.
//
// The groups make states compact (a group is stored as an index, not a bit per fact) and
// expose operators with mutex preconditions, which can never apply and are dropped.

#include "ground/ground_task.h"
#include "ground/reachability.h"

#include <vector>

namespace envdesign::ground {

// `fact_atoms[f]` is the atom of fact f ([predicate, objects...]), or empty for facts that
// are not atoms (complements). Sets task.mutex_groups to disjoint groups, removes operators
// whose preconditions are mutex, and makes a goal with mutex facts unreachable.
void add_mutex_groups(GroundTask &task, const std::vector<AtomKey> &fact_atoms);

} // namespace envdesign::ground
