#pragma once
// Grounding: a lifted Domain + Problem -> an integer GroundTask (ground_task.h).
//
// Only actions reachable in the delete relaxation are instantiated (a worklist over newly
// reached atoms, joining each action's positive preconditions). Static atoms are evaluated
// here and vanish; negative preconditions become complementary facts; facts and operators
// that cannot influence the goal are dropped (backward relevance). A goal that grounding
// already shows unreachable yields a task whose goal fact no operator adds, so the search
// proves it unsolvable.

#include "ground/ground_task.h"
#include "ground/stop.h"
#include "pddl/task.h"

namespace envdesign::ground {

struct GroundingStatistics {
    int reachable_atoms = 0;   // fluent and static, before relevance pruning
    int reachable_actions = 0; // before relevance pruning
    int relevant_facts = 0;
    int relevant_operators = 0;
};

// Throws pddl::ParseError when the input is wrong in a way only grounding reveals
// (e.g. an action cost refers to a function value the problem does not give), and
// GroundingStopped when `stop` says so (ground/stop.h). `prune_irrelevant` false keeps the
// operators that change no fact the goal needs: every plan of the model stays a plan of the
// task (the design engine follows arbitrary action sequences in it, design/behaviour/worst_case.h).
GroundTask ground(const pddl::Domain &domain, const pddl::Problem &problem,
                  GroundingStatistics *statistics = nullptr, const StopCheck &stop = {},
                  bool prune_irrelevant = true);

} // namespace envdesign::ground
