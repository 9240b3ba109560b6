#pragma once
// What each robot behaviour (the spec's robot_behaviour, SPEC.md) means to the engine, in one
// place: how a task is evaluated, and the facts the objective and the searches rely on. The
// rest of the engine asks a Behaviour instead of comparing RobotBehaviour values, so a new
// behaviour is one row of the table in behaviour.cc.
//
// A task's evaluation for a behaviour is evaluate_task.h's.
//
//   const Behaviour &b = behaviour_of(problem.weights.behaviour);
//   if (b.may_explain) ...

#include "design/design_problem.h"

namespace envdesign::design {

struct Behaviour {
    RobotBehaviour id;
    const char *name; // as in the spec file and the messages: "EXPLICABLE", ...

    // EXPLICABLE: the robot takes the most explicable plan within its means (the paper),
    // so a design's plans only get less explicable as modifications restrict: the witness
    // bound's floors hold (docs/design-search.md).
    bool takes_most_explicable_plan;
    // COST_OPTIMAL and COST_OPTIMAL_BEST_CASE: the robot runs some optimal plan of P_R, we do
    // not know which (cost_optimal.h); IE is the largest over them, or with `best_case` the
    // least.
    bool runs_an_optimal_plan;
    bool best_case;
    // EXPLAINING: the robot may follow its own optimal plan and explain it instead
    // (explaining.h); the objective chooses per task (objective.h).
    bool may_explain;
    // A task's value under a design depends only on its witness plans (the cones, the
    // inheritance of evaluations and settled tasks of the witness search). Not with
    // explanations: they depend on every model difference, witnessed or not.
    bool value_follows_witnesses;
    // The witnesses are every action of every optimal plan, not the plan alone (the worst
    // case: any optimal plan may be the one the robot runs).
    bool every_optimal_action_witnesses;
};

const Behaviour &behaviour_of(RobotBehaviour id);

} // namespace envdesign::design
