#include "design/reconciliation/explanation_hitting.h"

#include "design/behaviour/explicability.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <cctype>
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
    ModelPair told; // the human's side alone: the validator reads nothing else
    told.human_domain = models.human_domain;
    told.human_problem = models.human_problem;
    apply_difference(search.differences[d], models, told);
    return validate::validate_plan(told.human_domain, told.human_problem, plan).valid;
}

// What a plan of P_H reads: the schemas of its steps, and the ground atoms their
// preconditions and the goal read. A restricting difference about neither cannot break the
// plan alone (it reads nothing negatively, and effects are unconditional: removing an
// initial atom no step reads changes no step), so the validator is asked only about the
// others. `known` false: a step did not match a schema; every difference is checked.
struct PlanReads {
    bool known = false;
    std::set<std::string> schemas;
    std::set<pddl::Atom> atoms;
};

PlanReads plan_reads(const ModelPair &models, const std::vector<std::string> &plan) {
    PlanReads reads;
    for (const auto &step : plan) {
        std::vector<std::string> words;
        std::string word;
        for (char c : step) {
            bool separator = c == '(' || c == ')' || std::isspace(static_cast<unsigned char>(c));
            if (!separator)
                word += c;
            else if (!word.empty())
                words.push_back(std::move(word)), word.clear();
        }
        if (!word.empty())
            words.push_back(std::move(word));
        const pddl::Action *action =
            words.empty() ? nullptr : models.human_domain.find_action(words[0]);
        if (!action || action->parameters.size() + 1 != words.size())
            return {};
        reads.schemas.insert(action->name);
        for (const auto &l : action->precondition) {
            pddl::Atom ground{l.atom.predicate, {}, {}};
            for (const auto &arg : l.atom.args) {
                auto it = std::find_if(action->parameters.begin(), action->parameters.end(),
                                       [&](const pddl::TypedName &p) { return p.name == arg; });
                ground.args.push_back(it == action->parameters.end()
                                          ? arg
                                          : words[1 + (it - action->parameters.begin())]);
            }
            reads.atoms.insert(std::move(ground));
        }
    }
    for (const auto &l : models.human_problem.goal)
        reads.atoms.insert(l.atom);
    reads.known = true;
    return reads;
}

bool may_break(const ModelDifference &d, const PlanReads &reads) {
    if (!reads.known || d.kind == DifferenceKind::GOAL)
        return true;
    if (d.kind == DifferenceKind::INIT)
        return reads.atoms.count(d.literal.atom) > 0;
    return reads.schemas.count(d.action) > 0; // a schema's precondition, effect, or itself
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
            std::vector<int> sorted = chosen;
            std::sort(sorted.begin(), sorted.end());
            if (!found || sorted.size() < best.size() ||
                (sorted.size() == best.size() && sorted < best)) {
                best = std::move(sorted);
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
    return best;
}

namespace {

// The candidates (differences that keep pi_R) that `plan` does not survive alone.
std::vector<int> breaking_alone(const ModelPair &models, const ExplanationSearch &search,
                                const std::vector<bool> &breaks_robot,
                                const std::vector<std::string> &plan) {
    PlanReads reads = plan_reads(models, plan);
    std::vector<int> hit;
    for (int d = 0; d < static_cast<int>(breaks_robot.size()); ++d)
        if (!breaks_robot[d] && may_break(search.differences[d], reads) &&
            !valid_with(models, search, d, plan))
            hit.push_back(d);
    return hit;
}

// The sets T of the plans earlier searches met (PlanCache::cheaper_plans) that are plans of
// P_H here and cheaper than pi_R (cost `robot_cost`): the argument above holds for any such
// plan, wherever it was found. False when one has an empty T (no explanation exists).
bool sets_of_known_plans(const ModelPair &models, const std::vector<std::string> &robot_plan,
                         long long robot_cost, const std::vector<bool> &breaks_robot,
                         const PlanCache &planner, const ExplanationSearch &search,
                         std::vector<std::vector<int>> &sets) {
    for (const auto &plan : planner.cheaper_plans(robot_plan)) {
        auto v = validate::validate_plan(models.human_domain, models.human_problem, plan);
        if (!v.valid || v.cost >= robot_cost)
            continue;
        std::vector<int> hit = breaking_alone(models, search, breaks_robot, plan);
        if (hit.empty())
            return false;
        if (std::find(sets.begin(), sets.end(), hit) == sets.end())
            sets.push_back(std::move(hit));
    }
    return true;
}

} // namespace

void hitting_set_explanation(const ModelPair &models, const std::vector<std::string> &robot_plan,
                             PlanCache &planner, const Deadline &deadline,
                             ExplanationSearch &search) {
    search.hitting_sets = true;
    int n = static_cast<int>(search.differences.size());
    auto robot = validate::validate_plan(models.human_domain, models.human_problem, robot_plan);
    if (!robot.valid) {
        search.status = ExplanationStatus::NONE; // and no restricting difference can mend it
        return;
    }
    PlanReads robot_reads = plan_reads(models, robot_plan);
    std::vector<bool> breaks_robot(n);
    for (int d = 0; d < n; ++d)
        breaks_robot[d] = may_break(search.differences[d], robot_reads) &&
                          !valid_with(models, search, d, robot_plan);
    std::vector<std::vector<int>> sets;
    if (!sets_of_known_plans(models, robot_plan, robot.cost, breaks_robot, planner, search, sets)) {
        search.status = ExplanationStatus::NONE;
        return;
    }
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
        if (best.status == PlanStatus::SOLVED && v.valid && best.cost < v.cost)
            planner.remember_cheaper_plan(robot_plan, best.plan);
        std::vector<int> hit = breaking_alone(models, search, breaks_robot, best.plan);
        if (hit.empty()) {
            search.status = ExplanationStatus::NONE;
            return;
        }
        sets.push_back(std::move(hit));
    }
}

} // namespace envdesign::design
