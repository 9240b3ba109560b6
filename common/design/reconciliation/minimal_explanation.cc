#include "design/reconciliation/minimal_explanation.h"

#include "design/behaviour/explicability.h"
#include "design/reconciliation/explanation_hitting.h"
#include "validate/plan_validator.h"

#include <algorithm>

namespace envdesign::design {
namespace {

// Human plans cheaper than pi_R met so far in one search (the human's own optimal plan
// first). One still valid and cheaper in P_H + E proves that pi_R is not optimal there, the
// planner's answer, without a search; so the subsets tried, and the explanation, stay the same.
class CheaperPlans {
public:
    void add(std::vector<std::string> plan) {
        if (!plan.empty() && std::find(plans_.begin(), plans_.end(), plan) == plans_.end())
            plans_.push_back(std::move(plan));
    }
    // Whether a kept plan is valid in `told` at a human cost below `robot_plan_cost`.
    bool refutes(const ModelPair &told, long long robot_plan_cost) const {
        for (const auto &plan : plans_) {
            validate::Validation v =
                validate::validate_plan(told.human_domain, told.human_problem, plan);
            if (v.valid && v.cost < robot_plan_cost)
                return true;
        }
        return false;
    }

private:
    std::vector<std::vector<std::string>> plans_;
};

// plan_optimal_for_human, answered by `cheaper` where it can; a cheaper optimal plan the
// planner finds joins it.
std::optional<bool> optimal_for_human(const ModelPair &told, long long robot_plan_cost,
                                      CheaperPlans &cheaper, PlanCache &planner,
                                      const Deadline &deadline) {
    if (cheaper.refutes(told, robot_plan_cost))
        return false;
    PlanOutcome best = solve_model(told.human_domain, told.human_problem, planner, deadline);
    if (best.status == PlanStatus::LIMIT)
        return std::nullopt;
    if (best.status == PlanStatus::SOLVED && best.cost < robot_plan_cost)
        cheaper.add(std::move(best.plan));
    return best.status == PlanStatus::SOLVED && best.cost == robot_plan_cost;
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
    CheaperPlans cheaper;
    PlanOutcome human = solve_model(models.human_domain, models.human_problem, planner, deadline);
    if (human.status == PlanStatus::LIMIT)
        return search; // LIMIT
    cheaper.add(std::move(human.plan));
    for (int k = 0; k <= n; ++k) {
        std::vector<int> subset(k);
        for (int i = 0; i < k; ++i)
            subset[i] = i;
        do {
            if (deadline.expired())
                return search; // LIMIT
            ++search.subsets_tried;
            ModelPair told = told_models(models, search.differences, subset);
            validate::Validation v =
                validate::validate_plan(told.human_domain, told.human_problem, robot_plan);
            if (!v.valid)
                continue;
            ++search.planner_checks;
            std::optional<bool> optimal =
                optimal_for_human(told, v.cost, cheaper, planner, deadline);
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
