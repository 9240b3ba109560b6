#pragma once
// Independent reference values for the design tests: explicability by enumerating action
// sequences and checking each with the plan validator (validate/, which shares no code with
// the compilation, the grounder's relevance analysis or the search).

#include "design/behaviour/explicability.h"
#include "design/model/configuration.h"
#include "ground/grounder.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace envdesign::design::testing {

struct BruteForce {
    double human_optimal_cost = INF; // least cost of a sequence valid in P_H
    double human_plan_cost = INF;    // least human cost of a sequence valid in both
    double robot_cost = INF;         // least robot cost among those
};

class BruteForceSearch {
public:
    BruteForceSearch(const ModelPair &models, int max_length)
        : models_(models), max_length_(max_length) {
        std::set<std::string> names;
        for (const auto &op : ground::ground(models.robot_domain, models.robot_problem).operators)
            names.insert(op.name);
        for (const auto &op : ground::ground(models.human_domain, models.human_problem).operators)
            names.insert(op.name);
        alphabet_.assign(names.begin(), names.end());
    }

    BruteForce run() {
        std::vector<std::string> plan;
        extend(plan, true);  // sequences executable in both models
        extend(plan, false); // sequences executable in the human's model
        return best_;
    }

private:
    // A prefix is worth extending when every step applies (only the goal may be missing).
    static bool executable(const validate::Validation &v) { return v.valid || v.failed_step < 0; }

    void extend(std::vector<std::string> &plan, bool both) {
        auto human = validate::validate_plan(models_.human_domain, models_.human_problem, plan);
        if (!executable(human))
            return;
        if (both) {
            auto robot = validate::validate_plan(models_.robot_domain, models_.robot_problem, plan);
            if (!executable(robot))
                return;
            if (robot.valid && human.valid) {
                double h = static_cast<double>(human.cost), r = static_cast<double>(robot.cost);
                if (h < best_.human_plan_cost ||
                    (h == best_.human_plan_cost && r < best_.robot_cost)) {
                    best_.human_plan_cost = h;
                    best_.robot_cost = r;
                }
            }
        } else if (human.valid) {
            best_.human_optimal_cost =
                std::min(best_.human_optimal_cost, static_cast<double>(human.cost));
        }
        if (static_cast<int>(plan.size()) >= max_length_)
            return;
        for (const auto &step : alphabet_) {
            plan.push_back(step);
            extend(plan, both);
            plan.pop_back();
        }
    }

    const ModelPair &models_;
    int max_length_;
    std::vector<std::string> alphabet_;
    BruteForce best_;
};

inline BruteForce brute_force_explicability(const ModelPair &models, int max_length) {
    return BruteForceSearch(models, max_length).run();
}

} // namespace envdesign::design::testing
