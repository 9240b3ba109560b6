#include "design/search/explanation_bound.h"

#include "design/model/configuration.h"
#include "design/reconciliation/explanation_hitting.h"
#include "design/search/witness.h"
#include "validate/plan_validator.h"

#include <set>
#include <string>

namespace envdesign::design::witness {

ExplanationBound::ExplanationBound(const DesignProblem &problem, const TouchIndex &index,
                                   const std::vector<Record> &root)
    : index_(index) {
    for (int m = 0; m < index.size(); ++m) {
        every_.push_back(m);
        if (index.of(m).edits_robot || !index.of(m).restricting)
            relaxing_.push_back(m);
    }
    for (int t = 0; t < static_cast<int>(problem.tasks.size()); ++t) {
        Task task;
        const Record &r = t < static_cast<int>(root.size()) ? root[t] : nullptr;
        const TaskExplanation *x =
            r && r->evaluation.explanation ? &*r->evaluation.explanation : nullptr;
        if (problem.tasks[t].probability > 0 && x && !x->robot_plan.empty()) {
            task.models = configured_models(problem, {}, t);
            // Every difference, not only the relevant ones: a bound needs no pruning argument.
            task.differences = model_differences(task.models, false);
            validate::Validation v = validate::validate_plan(
                task.models.human_domain, task.models.human_problem, x->robot_plan);
            if (v.valid)
                task.robot_plan_cost = static_cast<double>(v.cost);
        }
        tasks_.push_back(std::move(task));
    }
}

const ExplanationBound::Breakers &ExplanationBound::breaking(int t, const PooledPlan &plan) const {
    const Task &task = tasks_[t];
    auto [entry, fresh] = task.breaking.try_emplace(plan.steps.get());
    if (!fresh)
        return entry->second;
    Breakers &out = entry->second;
    // Touching with every modification's added preconditions read: a superset of any design's.
    auto touching = index_.touching_human_plan(every_, t, *plan.steps);
    if (touching)
        out.modifications = std::move(*touching);
    else // not a plan of this model: every modification may break it
        out.modifications = every_;
    std::set<std::string> atoms; // read by a step's precondition or by the goal
    std::set<std::string> schemas;
    bool known = true;
    for (const auto &l : task.models.human_problem.goal)
        atoms.insert(l.atom.to_string());
    for (const auto &step : *plan.steps) {
        std::vector<std::string> words = words_of(step);
        const pddl::Action *action =
            words.empty() ? nullptr : task.models.human_domain.find_action(words[0]);
        if (!action || action->parameters.size() + 1 != words.size()) {
            known = false; // not a step of this model: any difference may break it
            break;
        }
        schemas.insert(action->name);
        for (const auto &l : action->precondition)
            atoms.insert(ground_atom(l.atom, *action, words));
    }
    for (int i = 0; i < static_cast<int>(task.differences.size()); ++i) {
        const ModelDifference &d = task.differences[i];
        bool breaks = !known;
        switch (d.kind) {
        case DifferenceKind::INIT:
            breaks = breaks || atoms.count(d.literal.atom.to_string()) > 0;
            break;
        case DifferenceKind::GOAL: // a goal literal told: the plan may not reach it
            breaks = breaks || d.robot_has;
            break;
        case DifferenceKind::PRECONDITION: // a removed precondition only adds plans
            breaks = breaks || (d.robot_has && schemas.count(d.action) > 0);
            break;
        case DifferenceKind::ACTION: // a schema told only adds plans
            breaks = breaks || (!d.robot_has && schemas.count(d.action) > 0);
            break;
        case DifferenceKind::ADD_EFFECT:
        case DifferenceKind::DELETE_EFFECT:
            breaks = breaks || schemas.count(d.action) > 0;
            break;
        }
        if (breaks)
            out.differences.push_back(i);
    }
    return out;
}

std::vector<std::pair<std::vector<std::string>, double>>
ExplanationBound::explanation_plans(const DesignProblem &problem, const Configuration &design,
                                    int t, const TaskExplanation &x, const Deadline &deadline) {
    std::vector<std::pair<std::vector<std::string>, double>> out;
    Task &task = tasks_[t];
    if (!task.robot_plan_cost || !x.found || x.differences.empty() || x.robot_plan.empty())
        return out; // nothing cheaper to break, or no bound on explaining to sharpen
    ModelPair models = configured_models(problem, design, t);
    ExplanationSearch search;
    search.differences = model_differences(models);
    if (!all_restricting(models, search.differences))
        return out; // the subset enumeration keeps no plans: nothing to harvest
    hitting_set_explanation(models, x.robot_plan, planner_, deadline, search);
    // The cache keeps plans met under every design: each is checked against this one.
    for (auto &plan : planner_.cheaper_plans(x.robot_plan)) {
        if (task.returned.count(plan))
            continue;
        auto v = validate::validate_plan(models.human_domain, models.human_problem, plan);
        if (!v.valid)
            continue;
        task.returned.insert(plan);
        out.emplace_back(std::move(plan), static_cast<double>(v.cost));
    }
    return out;
}

} // namespace envdesign::design::witness
