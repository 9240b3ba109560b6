#pragma once
// Floors on the most explicable plan's human cost when some modifications add plans (a new
// lane, a door opened, a rule relaxed: ModificationClass::adding).
//
// With restricting modifications only, c_H(pi) in any design is at least its value with no
// modification: plans are only removed. An adding modification e can lower it, but only
// through plans that use e. So, per task t and adding modification e, let L(t, e) be the
// least human cost of a plan of P_mod that uses e, in the design A of every adding
// modification. Then for every design S:
//
//     c_H(pi_S) >= min( c_H(pi_{}), min over adding e in S of L(t, e) ).
//
// Why. Restricting modifications only remove plans and adding ones only add them, so every
// plan of S is a plan of A at the same cost. A plan of S that is also a plan of S's
// restricting part costs at least c_H(pi_{}). One that is not depends on some adding
// modification e of S: it has a step of a schema e edits, or a step whose precondition reads
// an initial atom e adds or removes, or e edits the goal. L(t, e) is the least cost of a
// plan of A with such a step (the goal case: of any plan of A), so the plan costs at least
// that. The robot's optimal cost c_R*, a floor on c_R(pi), falls the same way (the same
// argument on the robot's model alone).
// "Uses" is read on the ground task of A, built without pruning irrelevant operators so
// that every plan of A is a plan of it; a step is an operator. A task of at most 100 000
// states is explored whole once, which gives the least cost of a plan through each operator
// (search/state_space.h); a larger one gets A* with one more fact, set by the operators that
// use e and required by the goal. Before searching, h^max of an operator's precondition
// plus its cost bounds every plan that uses it from below: where that bound is above the
// floor for each operator of e, e cannot lower it and no search is made. A search that
// passes a second stops, and what it proved stands in for L(t, e): the largest f it expanded
// (LM-cut is admissible, so no plan using e costs less), or the least cost of any plan of A
// if that is more. A weaker floor, never a wrong one.

#include "design/design_problem.h"
#include "design/search/deadline.h"
#include "design/search/witness.h"

#include <optional>
#include <string>
#include <vector>

namespace envdesign::design {

struct UseFloor {
    int modification = 0;
    double cost = 0; // L(t, modification)
};

struct AdditionFloors {
    // Per task, the adding modifications whose L(t, e) is at most the task's floor (the
    // others cannot lower it), by modification.
    std::vector<std::vector<UseFloor>> below;
    // The same for the robot's optimal cost c_R* (a floor on c_R(pi)): the least robot cost
    // of a plan of A's robot model that uses e, where at most the task's robot floor.
    std::vector<std::vector<UseFloor>> robot_below;
    long long searches = 0; // A* runs
    double seconds = 0;
};

// L(t, e) for every task of positive probability and every modification in `adding`
// (ascending, each ModificationClass::adding), kept where it is at most `floor[t]` (none
// searched where that is -INF), and the robot's where `robot_floor[t]` is known. nullopt, with
// `why`, when a model does not ground or the deadline passes first.
std::optional<AdditionFloors> addition_floors(const DesignProblem &problem,
                                              const std::vector<int> &adding,
                                              const std::vector<double> &floor,
                                              const std::vector<std::optional<double>> &robot_floor,
                                              const Deadline &deadline, std::string &why);

} // namespace envdesign::design
