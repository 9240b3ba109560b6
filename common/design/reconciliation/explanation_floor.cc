#include "design/reconciliation/explanation_floor.h"

#include "design/reconciliation/model_differences.h"
#include "design/reconciliation/plan_reads.h"
#include "validate/plan_validator.h"

namespace envdesign::design {
namespace {

// Whether `plan` is valid in P_H + `told` at a human cost below `below`.
bool still_cheaper(const ModelPair &models, const std::vector<ModelDifference> &differences,
                   const std::vector<int> &told, const std::vector<std::string> &plan,
                   double below) {
    ModelPair human = told_human_model(models, differences, told);
    validate::Validation v = validate::validate_plan(human.human_domain, human.human_problem, plan);
    return v.valid && static_cast<double>(v.cost) < below;
}

} // namespace

int explanation_floor(const ModelPair &models, const std::vector<std::string> &human_plan,
                      double robot_cost_floor, long long max_subsets) {
    std::vector<ModelDifference> differences = model_differences(models);
    if (!still_cheaper(models, differences, {}, human_plan, robot_cost_floor))
        return 0;
    PlanReads reads = plan_reads(models, human_plan);
    std::vector<int> relevant;
    for (int d = 0; d < static_cast<int>(differences.size()); ++d)
        if (may_break(differences[d], reads))
            relevant.push_back(d);
    int n = static_cast<int>(relevant.size());
    long long tried = 0;
    for (int k = 1; k <= n; ++k) {
        std::vector<int> subset(k);
        for (int i = 0; i < k; ++i)
            subset[i] = i;
        do {
            if (++tried > max_subsets)
                return k;
            std::vector<int> told;
            for (int i : subset)
                told.push_back(relevant[i]);
            if (!still_cheaper(models, differences, told, human_plan, robot_cost_floor))
                return k;
        } while (next_subset(subset, n));
    }
    return n + 1;
}

} // namespace envdesign::design
