#pragma once
// Independent reference values for COST_OPTIMAL and COST_OPTIMAL_BEST_CASE: every
// cost-optimal plan of P_R is enumerated, by depth-first search over action sequences, each
// checked with the plan validator (validate/, which shares no code with the grounder, the
// search or design/behaviour/optimal_plan_graph.h), and looked at in P_H.
//
// Sequences are built from every action of either lifted domain applied to every tuple of
// objects (no grounding, so no relevance pruning either). With zero-cost actions there are
// infinitely many optimal plans; the enumeration stops a sequence where the pair (robot
// state, human state) repeats one earlier on it. A plan with such a repeat is a shorter plan
// with a cycle inserted: the cycle costs the robot nothing (else the shorter plan would be
// cheaper than optimal), and if it costs the human something, going round it k times makes
// the human cost unbounded. That is recorded when the repeated point still leads to a
// complete optimal plan (the anchor's subtree found one).

#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::design::testing {

struct OptimalPlansReference {
    double robot_optimal_cost = INF; // c_R*
    double human_optimal_cost = INF; // c_H*
    bool any_invalid = false;        // an optimal robot plan is not a valid plan of P_H
    bool unbounded = false;          // a zero-robot-cost cycle with human cost > 0
    double worst = -1;               // largest human cost of a valid optimal plan; -1: none
    double best = INF;               // least human cost of a valid optimal plan
    long long plans = 0;             // optimal plans seen (without repeats)
    bool exhausted = false;          // the node budget ran out: values unknown

    double worst_human_cost() const { return any_invalid || unbounded || worst < 0 ? INF : worst; }
    double best_human_cost() const { return best; }
};

class OptimalPlanEnumeration {
public:
    OptimalPlanEnumeration(const ModelPair &models, long long budget)
        : models_(models), budget_(budget) {
        add_alphabet(models.robot_domain, models.robot_problem);
        add_alphabet(models.human_domain, models.human_problem);
    }

    OptimalPlansReference run() {
        std::vector<std::string> plan;
        std::set<std::vector<std::string>> seen;
        result_.robot_optimal_cost = cheapest(models_.robot_domain, models_.robot_problem);
        result_.human_optimal_cost = cheapest(models_.human_domain, models_.human_problem);
        if (std::isinf(result_.robot_optimal_cost) || result_.exhausted)
            return result_;
        enumerate(plan);
        return result_;
    }

private:
    using Point = std::pair<std::vector<std::string>, std::vector<std::string>>; // robot, human
    struct Step {
        Point point;
        long long robot_cost, human_cost;
        bool cycle_with_human_cost = false; // a repeat of this point cost the human > 0
    };

    void add_alphabet(const pddl::Domain &domain, const pddl::Problem &problem) {
        std::vector<std::string> objects;
        for (const auto &o : problem.objects)
            objects.push_back(o.name);
        for (const auto &c : domain.constants)
            objects.push_back(c.name);
        for (const auto &action : domain.actions) {
            std::vector<std::string> tuple;
            add_tuples(action.name, action.parameters.size(), objects, tuple);
        }
        std::sort(alphabet_.begin(), alphabet_.end());
        alphabet_.erase(std::unique(alphabet_.begin(), alphabet_.end()), alphabet_.end());
    }
    void add_tuples(const std::string &name, std::size_t arity,
                    const std::vector<std::string> &objects, std::vector<std::string> &tuple) {
        if (tuple.size() == arity) {
            std::string step = "(" + name;
            for (const auto &o : tuple)
                step += " " + o;
            alphabet_.push_back(step + ")");
            return;
        }
        for (const auto &o : objects) {
            tuple.push_back(o);
            add_tuples(name, arity, objects, tuple);
            tuple.pop_back();
        }
    }

    bool spend() {
        if (--budget_ < 0)
            result_.exhausted = true;
        return !result_.exhausted;
    }

    // The least cost of a valid plan of one model: depth first, no state twice on a path
    // (a cheapest plan never needs a repeat), a state kept only when reached more cheaply.
    double cheapest(const pddl::Domain &domain, const pddl::Problem &problem) {
        std::map<std::vector<std::string>, long long> best_g;
        double best = INF;
        std::vector<std::string> plan;
        std::function<void()> go = [&] {
            if (!spend())
                return;
            auto v = validate::validate_plan(domain, problem, plan);
            if (v.failed_step >= 0 || v.executed_cost >= best)
                return;
            auto [it, fresh] = best_g.try_emplace(v.final_state, v.executed_cost);
            if (!fresh && it->second <= v.executed_cost && !plan.empty())
                return;
            it->second = v.executed_cost;
            if (v.valid)
                best = std::min(best, static_cast<double>(v.executed_cost));
            for (const auto &step : alphabet_) {
                plan.push_back(step);
                go();
                plan.pop_back();
            }
        };
        go();
        return best;
    }

    // True when some complete optimal plan extends `plan`.
    bool enumerate(std::vector<std::string> &plan) {
        if (!spend())
            return false;
        auto robot = validate::validate_plan(models_.robot_domain, models_.robot_problem, plan);
        if (robot.failed_step >= 0 ||
            static_cast<double>(robot.executed_cost) > result_.robot_optimal_cost)
            return false;
        auto human = validate::validate_plan(models_.human_domain, models_.human_problem, plan);
        bool human_ok = human.failed_step < 0;
        Point point{robot.final_state,
                    human_ok ? human.final_state : std::vector<std::string>{"<not valid>"}};
        for (auto &earlier : path_)
            if (earlier.point == point) {
                if (human_ok && earlier.robot_cost == robot.executed_cost &&
                    human.executed_cost > earlier.human_cost)
                    earlier.cycle_with_human_cost = true;
                return false; // the anchor's subtree covers every continuation
            }
        path_.push_back({point, robot.executed_cost, human.executed_cost});
        bool found = false;
        if (robot.valid && static_cast<double>(robot.executed_cost) == result_.robot_optimal_cost) {
            found = true;
            ++result_.plans;
            if (human.valid) {
                double cost = static_cast<double>(human.cost);
                result_.worst = std::max(result_.worst, cost);
                result_.best = std::min(result_.best, cost);
            } else {
                result_.any_invalid = true;
            }
        }
        for (const auto &step : alphabet_) {
            plan.push_back(step);
            found = enumerate(plan) || found;
            plan.pop_back();
        }
        if (found && path_.back().cycle_with_human_cost)
            result_.unbounded = true;
        path_.pop_back();
        return found;
    }

    const ModelPair &models_;
    long long budget_;
    std::vector<std::string> alphabet_;
    std::vector<Step> path_;
    OptimalPlansReference result_;
};

// Every cost-optimal plan of models.robot_* as P_H sees it; gives up after `budget`
// sequences (result.exhausted).
inline OptimalPlansReference enumerate_optimal_plans(const ModelPair &models, long long budget) {
    return OptimalPlanEnumeration(models, budget).run();
}

} // namespace envdesign::design::testing
