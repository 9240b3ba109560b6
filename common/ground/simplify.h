#pragma once
// Exact simplifications of a GroundTask that keep every optimal plan.

#include "ground/ground_task.h"

namespace envdesign::ground {

// Drops operators not reachable in the delete relaxation from the initial state, and the
// facts that then never become true. Needed after negative preconditions were compiled into
// complementary facts, which the lifted exploration did not see.
void remove_unreachable(GroundTask &task);

// Drops facts that are true initially and that no operator deletes: they hold in every
// reachable state, so as preconditions and goals they say nothing (grid's open doors).
void remove_always_true(GroundTask &task);

// Drops facts that no precondition and no goal reads, and keeps every operator (one that
// then changes nothing stays, as a step that leaves the state as it is). Whether a sequence
// of operators is a plan, and what it costs, does not change; states that differed only in
// such facts become one (design/behaviour/optimal_plan_graph.h follows every plan of the task).
void remove_unread(GroundTask &task);

// Drops facts that no goal needs, directly or through the preconditions of an operator that
// changes a needed fact, and the operators left without effects. Operators kept keep all
// their preconditions, so a plan of the smaller task is a plan of the original.
void remove_irrelevant(GroundTask &task);

} // namespace envdesign::ground
