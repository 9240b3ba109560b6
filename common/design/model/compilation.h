#pragma once
// The compilation P_mod of an explicable planning problem <P_R, P_H> (the paper's
// "Compilation for Most Explicable Plan", SPEC.md "The model"):
//   - fluents: a robot copy f_R ("r-" + name) and a human copy f_H ("h-" + name) of every
//     predicate (and of every static numeric function); equality stays shared;
//   - actions: those present in both models (by name, same parameters), each with both
//     models' preconditions and both models' effects;
//   - initial state and goal: the unions of the renamed ones;
//   - cost: the human's cost of the action (primary), the robot's cost as the secondary
//     cost the search minimises among plans of least primary cost. A model whose problem
//     has no :metric costs 1 per action, as PDDL says.
// An optimal plan of P_mod is therefore a most explicable plan, and among those the
// cheapest for the robot.

#include "design/model/configuration.h"
#include "pddl/task.h"

#include <string>

namespace envdesign::design {

struct CompiledTask {
    pddl::Domain domain;
    pddl::Problem problem;
};

// Throws pddl::ParseError when the models disagree where they must agree: an action's
// parameter count or types, a type's parent, an object's type.
CompiledTask compile_explicable(const ModelPair &models);

// Whether every action both models have costs people at least what it costs the robot, in
// every instance. Then every plan of P_mod costs people at least the robot's optimum c_R*,
// so a task's IE is at least g(c_R* - c_H*) (explicability.h, ie_floor). Modifications edit
// neither action costs nor function values, so the spec's models answer for every design.
bool human_costs_dominate(const pddl::Domain &robot_domain, const pddl::Problem &robot_problem,
                          const pddl::Domain &human_domain, const pddl::Problem &human_problem);

// Whether every action both models have costs people exactly what it costs the robot, in
// every instance: then every plan of P_mod costs both the same.
bool costs_agree(const ModelPair &models);

std::string robot_copy(const std::string &name);
std::string human_copy(const std::string &name);

} // namespace envdesign::design
