#pragma once
// Which modifications can change a task's evaluation: the touch test of the witness search
// (witness_search.h).
//
// A modification is *restricting* when, combined with any other modifications, it only
// removes plans of P_R, P_H and P_mod and never makes a plan cheaper. Classified edit by
// edit, soundly (when unsure: not restricting):
//   - add_precondition (any literal), remove_action (a schema or one ground action), add_goal
//     and add_predicate are restricting;
//   - remove_init of an atom, add_effect of a delete (not p) and remove_effect of an add, for
//     a predicate that no precondition or goal uses negatively, are restricting, and so are
//     add_init, add_effect of an add and remove_effect of a delete for a predicate none uses
//     positively: every state reached then has fewer (more) atoms of that predicate and the
//     same others, so a plan valid after the edits was valid before, at the same cost;
//   - any init or effect edit of a *private fresh* predicate (declared by add_predicate and
//     mentioned by no other modification) is restricting: that fluent is read only by the
//     modification's own added preconditions, so dropping it maps every plan of the modified
//     model to a plan of the model without the modification, at the same cost. A fresh
//     predicate that several modifications mention follows the rules above (one may add
//     the atoms another one's precondition needs);
//   - remove_precondition, remove_goal, and the other init and effect edits are not.
// "Uses" are collected over both domains, every task's goals and every modification's added
// preconditions and goals, per model (the compilation keeps the robot's and the human's
// fluents apart).
//
// A modification *touches* a witness (an optimal plan found for a configuration) when it
// changes something the plan's validity or cost depends on: a precondition or effect of a
// schema the plan uses (or removes it, or one of its ground actions), an init atom that one
// of its steps or the goal needs (remove_init) or needs absent (add_init). add_goal touches
// every witness of the model it edits. Robot-model edits touch P_mod's witness only, human
// ones both P_mod's and P_H's. For COST_OPTIMAL(_BEST_CASE) robots `plan` is the worst (best)
// cost-optimal plan and stands in for P_mod's witness; with a finite worst case, its human
// side is every action of every optimal plan (TaskExplicability::optimal_actions).

#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace envdesign::design {

struct ModificationClass {
    bool restricting = true; // every edit is restricting
    // The robot's optimal cost never drops with it: every edit of the robot's model is
    // restricting, or they only gate (gated_twins.h).
    bool robot_restricting = true;
    bool human_restricting = true; // the same for the human's model and c_H*
    bool edits_robot = false;      // it edits the robot's model at all
    bool edits_human = false;      // it edits the human's model at all
    // Every edit only adds plans and never makes one dearer, whatever else is added (the
    // mirror of the restricting rules: more atoms of a predicate nothing reads negatively,
    // fewer of one nothing reads positively, a precondition or goal removed). A new lane.
    bool adding = true;
    std::string why_not; // the first edit that is not restricting, for the result
};

// "(move c00 c10)" -> {"move", "c00", "c10"}
std::vector<std::string> words_of(const std::string &step);

// `atom` of `action`'s schema with its parameters bound to a step's `arguments` (words_of).
std::string ground_atom(const pddl::Atom &atom, const pddl::Action &action,
                        const std::vector<std::string> &arguments);

// One TouchIndex serves one search (it memoizes, and is not thread-safe).
// Ascending lists of the restricting modifications that touch an evaluation's witnesses.
struct WitnessTouch {
    // False when a witness is missing (an evaluation with no human plan): nothing can be
    // said, and every modification must be assumed to touch it.
    bool known = true;
    std::vector<int> explicable; // touch pi, the most explicable plan
    std::vector<int> human;      // touch the human's optimal plan
    std::vector<int> all;        // either
};

class TouchIndex {
public:
    explicit TouchIndex(const DesignProblem &problem);

    const ModificationClass &of(int modification) const { return classes_[modification]; }
    int size() const { return static_cast<int>(classes_.size()); }
    // Per modification, whether it never lowers c_R* (ModificationClass::robot_restricting).
    std::vector<bool> robot_restricting() const {
        std::vector<bool> out;
        for (const auto &c : classes_)
            out.push_back(c.robot_restricting);
        return out;
    }
    // The same for c_H* (ModificationClass::human_restricting).
    std::vector<bool> human_restricting() const {
        std::vector<bool> out;
        for (const auto &c : classes_)
            out.push_back(c.human_restricting);
        return out;
    }

    // The restricting modifications that touch the witnesses of `evaluation`, an evaluation
    // of task `task` under `configuration`. What a step relies on is read from the spec's
    // domains and the configuration's added preconditions and goals (a superset of what the
    // configured models say, so never too few), without building the models.
    WitnessTouch touching(const Configuration &configuration, int task,
                          const TaskExplicability &evaluation) const;
    // The restricting modifications that touch `plan` as a plan of the human's model of
    // `task` under `configuration`; nullopt if a step is not an action of that model.
    std::optional<std::vector<int>> touching_human_plan(const Configuration &configuration,
                                                        int task,
                                                        const std::vector<std::string> &plan) const;
    // The same on the robot's side: the restricting modifications that can make `plan`
    // invalid (or dearer) as a plan of the robot's model; nullopt if a step is not an action
    // of that model.
    std::optional<std::vector<int>> touching_robot_plan(const Configuration &configuration,
                                                        int task,
                                                        const std::vector<std::string> &plan) const;

private:
    struct AddedLiteral {
        std::string action; // for an added precondition; empty for an added goal
        pddl::Literal literal;
    };
    struct PlanTouch {
        std::vector<int> mods;
        bool known = true;
    };

    // Memoized: one plan under configurations that add the same preconditions and goals.
    const PlanTouch &plan_touch(int side, const Configuration &configuration, int task,
                                const std::vector<std::string> &plan) const;
    void add_key(const std::string &key, std::vector<int> &out) const;
    // Files `modification`'s edit of `side`'s model under the keys of what it changes.
    void index_edit(int modification, const Edit &edit, int side);
    std::vector<int> restricting_only(std::vector<int> mods, int side) const;

    const DesignProblem &problem_;
    std::vector<std::vector<AddedLiteral>> added_[2]; // per side, per modification
    mutable std::unordered_map<std::string, PlanTouch> memo_;

    std::vector<ModificationClass> classes_;
    std::unordered_map<std::string, std::vector<int>> by_key_;   // touch key -> modifications
    std::vector<int> every_robot_witness_, every_human_witness_; // add_goal
};

} // namespace envdesign::design
