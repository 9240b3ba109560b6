#include "design/model/configuration.h"

namespace envdesign::design {

ModelPair base_models(const DesignProblem &problem, int task) {
    const DesignTask &t = problem.tasks[task];
    return {problem.robot_domain, t.robot_problem, problem.human_domain, t.human_problem};
}

void apply_modification(const Modification &modification, ModelPair &models, ApplyMode mode) {
    for (const Edit &edit : modification.edits) {
        if (applies_to_robot(edit.model))
            apply_edit(edit, models.robot_domain, &models.robot_problem, mode);
        if (applies_to_human(edit.model))
            apply_edit(edit, models.human_domain, &models.human_problem, mode);
    }
}

ModelPair configured_models(const DesignProblem &problem, const Configuration &configuration,
                            int task) {
    ModelPair models = base_models(problem, task);
    for (int m : configuration)
        apply_modification(problem.modifications[m], models, ApplyMode::LENIENT);
    return models;
}

double design_cost(const DesignProblem &problem, const Configuration &configuration) {
    double cost = 0;
    for (int m : configuration)
        cost += problem.modifications[m].cost;
    return cost;
}

std::vector<std::string> design_names(const DesignProblem &problem,
                                      const Configuration &configuration) {
    std::vector<std::string> names;
    for (int m : configuration)
        names.push_back(problem.modifications[m].name);
    return names;
}

std::string to_string(const DesignProblem &problem, const Configuration &configuration) {
    std::string out = "{";
    for (std::size_t i = 0; i < configuration.size(); ++i)
        out += (i ? ", " : "") + problem.modifications[configuration[i]].name;
    return out + "}";
}

bool next_subset(std::vector<int> &subset, int n) {
    int k = static_cast<int>(subset.size());
    for (int i = k - 1; i >= 0; --i) {
        if (subset[i] < n - k + i) {
            ++subset[i];
            for (int j = i + 1; j < k; ++j)
                subset[j] = subset[j - 1] + 1;
            return true;
        }
    }
    return false;
}

} // namespace envdesign::design
