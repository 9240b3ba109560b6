#pragma once
// Overview: a design problem as the design engine sees it, after the spec file was read and
// checked (design_spec.h). This is the paper's DP_{Exp,D,T}: tasks (each a robot model P_R
// and a human model P_H, with a probability), modifications (sets of edits with a cost), the
// objective's weights, a discount and a horizon.
//
// A configuration (a subset of modifications) turns each task into a pair of edited models
// (configuration.h); the explicability of a pair is computed by compiling it (compilation.h,
// explicability.h); the objective combines the tasks (objective.h); the search ranges over
// configurations (design_search.h).

#include "design/model/edits.h"
#include "pddl/task.h"

#include <string>
#include <vector>

namespace envdesign::design {

enum class Distance { EXP_COST_DIFF, COST_DIFF };

// What the robot does in a task (SPEC.md): EXPLICABLE is the paper's setting.
enum class RobotBehaviour { EXPLICABLE, COST_OPTIMAL, COST_OPTIMAL_BEST_CASE, EXPLAINING };

struct ObjectiveWeights {
    double alpha = 1; // weight of f_T(E[IE])
    double beta = 1;  // weight of the design cost C(xi)
    double kappa = 1; // weight of T * E[c_R(pi)]
    double gamma = 1; // discount of inexplicability over the horizon, in [0, 1]
    int horizon = 1;  // T
    Distance distance = Distance::EXP_COST_DIFF;
    RobotBehaviour behaviour = RobotBehaviour::EXPLICABLE;
    double explanation_cost = 1; // EXPLAINING: per model difference, per repetition
};

struct DesignTask {
    std::string name;
    double probability = 1; // normalised: the tasks' probabilities sum to 1
    pddl::Problem robot_problem;
    pddl::Problem human_problem; // a copy of robot_problem when the spec gives none
};

struct Modification {
    std::string name;
    double cost = 0;
    std::vector<Edit> edits; // applied in order
};

struct DesignProblem {
    std::string file; // the spec file, for messages
    pddl::Domain robot_domain;
    pddl::Domain human_domain; // a copy of robot_domain when the spec gives none
    std::vector<DesignTask> tasks;
    std::vector<Modification> modifications;
    ObjectiveWeights weights;
    int max_design_size = 0; // 0: no limit
    double time_limit_s = 0; // 0: no limit
    // What the spec reader accepted but the author may not have meant ("SPEC:LINE:COL:
    // warning: ..."): task probabilities that do not sum to 1, a task whose two problems
    // have different goals.
    std::vector<std::string> warnings;
};

} // namespace envdesign::design
