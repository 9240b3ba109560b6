#pragma once
// Configurations: which modifications are applied. A configuration is the ascending list of
// the chosen modifications' indices (spec order); {} is the unmodified environment.
//
// configured_models() builds one task's robot and human models under a configuration: it
// copies the task's models and applies the chosen modifications' edits in spec order,
// LENIENT (the spec was checked STRICT, one modification at a time, when it was loaded).

#include "design/design_problem.h"

#include <string>
#include <vector>

namespace envdesign::design {

using Configuration = std::vector<int>;

// The robot's model P_R and the human's model P_H of one task.
struct ModelPair {
    pddl::Domain robot_domain;
    pddl::Problem robot_problem;
    pddl::Domain human_domain;
    pddl::Problem human_problem;
};

ModelPair base_models(const DesignProblem &problem, int task);

// Applies every edit of `modification` to the model(s) it targets.
void apply_modification(const Modification &modification, ModelPair &models, ApplyMode mode);

ModelPair configured_models(const DesignProblem &problem, const Configuration &configuration,
                            int task);

// C(xi): the sum of the chosen modifications' costs.
double design_cost(const DesignProblem &problem, const Configuration &configuration);

// The chosen modifications' names, in spec order.
std::vector<std::string> design_names(const DesignProblem &problem,
                                      const Configuration &configuration);

// "{barrier-a, barrier-b}" for logs.
std::string to_string(const DesignProblem &problem, const Configuration &configuration);

// Advances `subset` (ascending indices below n) to the next subset of its size in
// lexicographic order; false after the last one.
bool next_subset(std::vector<int> &subset, int n);

} // namespace envdesign::design
