#include "design/minimal_explanation.h"

#include "design/explanation_hitting.h"
#include "design/explicability.h"
#include "validate/plan_validator.h"

namespace envdesign::design {
namespace {

// The next k-subset of {0..n-1} in lexicographic order; false after the last.
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

} // namespace

std::optional<bool> plan_optimal_for_human(const ModelPair &told,
                                           const std::vector<std::string> &robot_plan,
                                           PlanCache &planner, const Deadline &deadline) {
    validate::Validation v =
        validate::validate_plan(told.human_domain, told.human_problem, robot_plan);
    if (!v.valid)
        return false;
    PlanOutcome best = solve_model(told.human_domain, told.human_problem, planner, deadline);
    if (best.status == PlanStatus::LIMIT)
        return std::nullopt;
    // pi_R is a plan, so P_H + E has one: UNSOLVABLE would be a planner bug.
    return best.status == PlanStatus::SOLVED && best.cost == v.cost;
}

ModelPair told_models(const ModelPair &models, const std::vector<ModelDifference> &differences,
                      const std::vector<int> &chosen) {
    ModelPair told = models;
    for (int i : chosen)
        apply_difference(differences[i], models, told);
    return told;
}

ExplanationSearch minimal_explanation(const ModelPair &models,
                                      const std::vector<std::string> &robot_plan,
                                      PlanCache &planner, const Deadline &deadline) {
    ExplanationSearch search;
    search.differences = model_differences(models);
    if (all_restricting(models, search.differences)) {
        hitting_set_explanation(models, robot_plan, planner, deadline, search);
        return search;
    }
    int n = static_cast<int>(search.differences.size());
    for (int k = 0; k <= n; ++k) {
        std::vector<int> subset(k);
        for (int i = 0; i < k; ++i)
            subset[i] = i;
        do {
            if (deadline.expired())
                return search; // LIMIT
            ++search.subsets_tried;
            ModelPair told = told_models(models, search.differences, subset);
            if (!validate::validate_plan(told.human_domain, told.human_problem, robot_plan).valid)
                continue;
            ++search.planner_checks;
            std::optional<bool> optimal =
                plan_optimal_for_human(told, robot_plan, planner, deadline);
            if (!optimal)
                return search; // LIMIT
            if (*optimal) {
                search.status = ExplanationStatus::FOUND;
                search.chosen = subset;
                return search;
            }
        } while (next_subset(subset, n));
    }
    search.status = ExplanationStatus::NONE;
    return search;
}

} // namespace envdesign::design
