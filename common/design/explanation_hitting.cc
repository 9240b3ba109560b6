#include "design/explanation_hitting.h"

#include "design/explicability.h"
#include "validate/plan_validator.h"

#include <functional>
#include <set>

namespace envdesign::design {
namespace {

std::set<std::string> negatively_read(const ModelPair &m) {
    std::set<std::string> out;
    for (const pddl::Domain *d : {&m.robot_domain, &m.human_domain})
        for (const auto &a : d->actions)
            for (const auto &l : a.precondition)
                if (l.negated)
                    out.insert(l.atom.predicate);
    for (const pddl::Problem *p : {&m.robot_problem, &m.human_problem})
        for (const auto &l : p->goal)
            if (l.negated)
                out.insert(l.atom.predicate);
    return out;
}

bool restricting(const ModelDifference &d, const std::set<std::string> &negative) {
    bool positive_only =
        !negative.count(d.literal.atom.predicate) && d.literal.atom.predicate != "=";
    switch (d.kind) {
    case DifferenceKind::INIT:
        return !d.robot_has && positive_only;
    case DifferenceKind::PRECONDITION:
    case DifferenceKind::GOAL:
        return d.robot_has && !d.literal.negated && positive_only;
    case DifferenceKind::DELETE_EFFECT:
        return d.robot_has && positive_only;
    case DifferenceKind::ADD_EFFECT:
        return !d.robot_has && positive_only;
    case DifferenceKind::ACTION:
        return !d.robot_has;
    }
    return false;
}

bool valid_with(const ModelPair &models, const ExplanationSearch &search, int d,
                const std::vector<std::string> &plan) {
    ModelPair told = told_models(models, search.differences, {d});
    return validate::validate_plan(told.human_domain, told.human_problem, plan).valid;
}

} // namespace

// Differences that add a requirement (a precondition or a goal) on a predicate.
bool adds_requirement(const ModelDifference &d) {
    return d.kind == DifferenceKind::PRECONDITION || d.kind == DifferenceKind::GOAL;
}

bool all_restricting(const ModelPair &models, const std::vector<ModelDifference> &differences) {
    std::set<std::string> negative = negatively_read(models);
    std::set<std::string> required, shrunk;
    for (const auto &d : differences) {
        if (!restricting(d, negative))
            return false;
        if (d.kind != DifferenceKind::ACTION)
            (adds_requirement(d) ? required : shrunk).insert(d.literal.atom.predicate);
    }
    // A requirement and a shrink on the same predicate break the union closure: Blocksworld's
    // (handempty) precondition alone or its delete alone keeps a two-block plan valid, both
    // together do not.
    for (const auto &p : required)
        if (shrunk.count(p))
            return false;
    return true;
}

std::vector<int> least_hitting_set(const std::vector<std::vector<int>> &sets, int size) {
    std::vector<int> chosen, best;
    std::vector<bool> in(size, false);
    bool found = false;
    // Branch on the elements of the first set not hit yet (smallest-first would be faster;
    // the sets here are few).
    std::function<void()> branch = [&] {
        if (found && chosen.size() + 1 > best.size())
            return; // cannot beat best: one more element at least is needed below
        const std::vector<int> *open = nullptr;
        for (const auto &s : sets) {
            bool hit = false;
            for (int e : s)
                hit = hit || in[e];
            if (!hit && (!open || s.size() < open->size()))
                open = &s;
        }
        if (!open) {
            if (!found || chosen.size() < best.size()) {
                best = chosen;
                found = true;
            }
            return;
        }
        for (int e : *open) {
            in[e] = true;
            chosen.push_back(e);
            branch();
            chosen.pop_back();
            in[e] = false;
        }
    };
    if (sets.empty())
        return {};
    branch();
    std::sort(best.begin(), best.end());
    return best;
}

void hitting_set_explanation(const ModelPair &models, const std::vector<std::string> &robot_plan,
                             PlanCache &planner, const Deadline &deadline,
                             ExplanationSearch &search) {
    search.hitting_sets = true;
    int n = static_cast<int>(search.differences.size());
    if (!validate::validate_plan(models.human_domain, models.human_problem, robot_plan).valid) {
        search.status = ExplanationStatus::NONE; // and no restricting difference can mend it
        return;
    }
    std::vector<bool> breaks_robot(n);
    for (int d = 0; d < n; ++d)
        breaks_robot[d] = !valid_with(models, search, d, robot_plan);
    std::vector<std::vector<int>> sets;
    while (!deadline.expired()) {
        std::vector<int> chosen = least_hitting_set(sets, n);
        ++search.subsets_tried;
        ModelPair told = told_models(models, search.differences, chosen);
        auto v = validate::validate_plan(told.human_domain, told.human_problem, robot_plan);
        PlanOutcome best = solve_model(told.human_domain, told.human_problem, planner, deadline);
        ++search.planner_checks;
        if (best.status == PlanStatus::LIMIT)
            return;
        if (best.status == PlanStatus::SOLVED && v.valid && best.cost == v.cost) {
            search.status = ExplanationStatus::FOUND;
            search.chosen = chosen;
            return;
        }
        std::vector<int> hit; // the candidates that break the cheaper plan alone
        for (int d = 0; d < n; ++d)
            if (!breaks_robot[d] && !valid_with(models, search, d, best.plan))
                hit.push_back(d);
        if (hit.empty()) {
            search.status = ExplanationStatus::NONE;
            return;
        }
        sets.push_back(std::move(hit));
    }
}

} // namespace envdesign::design
