#pragma once
// A design reduced to what its objective depends on: C(xi), E_D[IE] and E_D[c_R(pi)].
// Evaluations do not depend on alpha, beta, kappa, gamma or T, so a design point gives the
// design's objective under any weights (objective_at), which is what the break-even
// analysis (break_even.h) and the report's plots need. The objective is linear in alpha and
// in f_T (objective.h), except with robot_behaviour EXPLAINING: there each task's choice
// between explaining and acting explicably depends on the weights (explaining.h), so the
// point keeps the tasks' evaluations (without plans) and objective_at chooses again.

#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/objective/objective.h"

#include <vector>

namespace envdesign::design {

struct DesignPoint {
    Configuration configuration;
    double design_cost = 0;           // C(xi)
    double expected_ie = INF;         // E_D[IE]; INF if a task of positive probability has none
    double expected_robot_cost = INF; // E_D[c_R(pi)]
    // EXPLAINING only: each task's probability and evaluation (plans dropped), in task order.
    std::vector<double> probabilities;
    std::vector<TaskExplicability> explaining_tasks;
};

// The point of `configuration` from one evaluation per task of `problem` (all known).
DesignPoint design_point(const DesignProblem &problem, const Configuration &configuration,
                         const std::vector<TaskExplicability> &tasks);

// The objective of `point` under `weights`: equal, bit for bit, to objective_of() when the
// weights are the problem's.
Objective objective_at(const ObjectiveWeights &weights, const DesignPoint &point);

// The ranking key of `point` under `weights` (for ranks_before).
RankedDesign ranked_at(const ObjectiveWeights &weights, const DesignPoint &point);

} // namespace envdesign::design
