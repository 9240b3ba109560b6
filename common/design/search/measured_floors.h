#pragma once
// Floors measured in an evaluated design that has adding modifications (hitting_set.h,
// docs/design-search.md "Floors measured in a design").
//
// Let D be a design with restricting part R and adding part X. A design S that keeps every
// modification of R and adds none outside X has only plans that D has, at the same costs:
// restricting edits only remove plans and adding ones only add them, whatever else is chosen.
// So the least cost of any plan of S is at least D's. For the robot's model that is
// c_R*(S) >= c_R*(D), a floor on the robot's cost; for P_mod, the most explicable plan's
// human cost (the least over its plans) c_H(pi_S) >= c_H(pi_D).
//
// Where addition_floors.h's L(t, e) are weak (a design of every addition with plans much
// cheaper than any single addition gives), these floors are exact where they apply: the
// adding-only design X, evaluated, bounds every design whose additions are a subset of X.

#include "design/design_problem.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"

#include <optional>
#include <vector>

namespace envdesign::design::witness {

// The designs a floor holds in: they keep every modification of `restricting` and add none
// of `outside` (the adding modifications D lacks). For the robot's floor both count only
// modifications that edit the robot's model: the others leave its plans as they are.
struct Within {
    Configuration restricting;
    std::vector<int> outside;
};

struct MeasuredFloor {
    Within human_within, robot_within;
    std::vector<std::optional<double>> human; // per task, c_H(pi_D); unset: not a floor here
    std::vector<std::optional<double>> robot; // per task, a lower bound on c_R*(D)
};

// The floors of an evaluated design: `tasks` its evaluations (null: unknown), `robot_bounds`
// the evaluator's lower bounds on c_R* (unset: unknown), `edits_robot` per modification.
// `human_floors`: the behaviour takes the most explicable plan (EXPLICABLE), so c_H(pi) is
// the least over P_mod's plans. Nullopt when the design has no adding modification (the
// root's facts already hold there).
std::optional<MeasuredFloor> measured_floor(const Configuration &design,
                                            const std::vector<int> &adding,
                                            const std::vector<bool> &edits_robot,
                                            const std::vector<const TaskExplicability *> &tasks,
                                            const std::vector<std::optional<double>> &robot_bounds,
                                            bool human_floors);

} // namespace envdesign::design::witness
