#include "design/search/gated_twins.h"

#include "design/model/edits.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace envdesign::design {
namespace {

// A literal with the action's parameters written as their positions: twins may name them
// apart.
std::string positional(const pddl::Literal &l, const pddl::Action &action) {
    std::string out = (l.negated ? "-" : "+") + l.atom.predicate;
    for (const auto &arg : l.atom.args) {
        std::string value = arg;
        for (std::size_t i = 0; i < action.parameters.size(); ++i)
            if (action.parameters[i].name == arg)
                value = "#" + std::to_string(i);
        out += " " + value;
    }
    return out;
}

std::multiset<std::string> positional(const std::vector<pddl::Literal> &literals,
                                      const pddl::Action &action) {
    std::multiset<std::string> out;
    for (const auto &l : literals)
        out.insert(positional(l, action));
    return out;
}

std::multiset<std::string> positional(const std::vector<pddl::CostExpression> &costs,
                                      const pddl::Action &action) {
    std::multiset<std::string> out;
    for (const auto &c : costs)
        out.insert(std::to_string(c.constant) +
                   (c.function ? positional(pddl::Literal{*c.function, false}, action) : ""));
    return out;
}

// The literals of `action`'s precondition on `predicate`.
std::vector<pddl::Literal> reads_of(const pddl::Action &action, const std::string &predicate) {
    std::vector<pddl::Literal> out;
    for (const auto &l : action.precondition)
        if (l.atom.predicate == predicate)
            out.push_back(l);
    return out;
}

// Whether `twin` is `base` made stricter by needing `gate` true where base needs it false.
bool is_twin(const pddl::Action &base, const pddl::Action &twin, const std::string &gate) {
    if (base.parameters.size() != twin.parameters.size())
        return false;
    for (std::size_t i = 0; i < base.parameters.size(); ++i)
        if (base.parameters[i].types != twin.parameters[i].types)
            return false;
    pddl::Literal base_gate = reads_of(base, gate).front(),
                  twin_gate = reads_of(twin, gate).front();
    base_gate.negated = false;
    if (positional(base_gate, base) != positional(twin_gate, twin))
        return false;
    if (positional(base.effect, base) != positional(twin.effect, twin) ||
        positional(base.costs, base) != positional(twin.costs, twin) ||
        positional(base.secondary_costs, base) != positional(twin.secondary_costs, twin))
        return false;
    std::multiset<std::string> stricter = positional(twin.precondition, twin);
    for (const auto &l : base.precondition)
        if (l.atom.predicate != gate && !stricter.count(positional(l, base)))
            return false;
    return true;
}

// What one model gives the check: its domain, its tasks' problems and the edits that apply.
struct ModelView {
    const pddl::Domain &domain;
    std::vector<const pddl::Problem *> problems;
    std::vector<std::vector<const Edit *>> edits; // per modification
};

ModelView view_of(const DesignProblem &problem, bool robot) {
    ModelView v{robot ? problem.robot_domain : problem.human_domain, {}, {}};
    for (const auto &task : problem.tasks)
        v.problems.push_back(robot ? &task.robot_problem : &task.human_problem);
    for (const auto &m : problem.modifications) {
        auto &edits = v.edits.emplace_back();
        for (const auto &edit : m.edits)
            if (robot ? applies_to_robot(edit.model) : applies_to_human(edit.model))
                edits.push_back(&edit);
    }
    return v;
}

std::string predicate_of(const Edit &edit) { return as_literal(edit.expression).atom.predicate; }

// The schema an edit changes, if any.
std::string schema_of(const Edit &edit) {
    if (edit.kind != EditKind::REMOVE_ACTION)
        return edit.action;
    if (!edit.expression.is_list)
        return edit.expression.symbol;
    return edit.expression.items.empty() ? "" : edit.expression.items[0].to_string();
}

bool in_goal_or_added(const ModelView &v, const std::string &predicate) {
    for (const auto *p : v.problems)
        for (const auto &l : p->goal)
            if (l.atom.predicate == predicate)
                return true;
    for (const auto &edits : v.edits)
        for (const Edit *e : edits)
            if ((e->kind == EditKind::ADD_PRECONDITION || e->kind == EditKind::ADD_GOAL) &&
                predicate_of(*e) == predicate)
                return true;
    return false;
}

// The twins of `gate` if it is a gate of the model as gated_twins.h says, else nullopt.
std::optional<std::vector<const pddl::Action *>> twins_of_gate(const ModelView &v,
                                                               const std::string &gate) {
    std::vector<const pddl::Action *> bases, twins;
    for (const auto &action : v.domain.actions) {
        for (const auto &l : action.effect)
            if (l.atom.predicate == gate)
                return std::nullopt;
        std::vector<pddl::Literal> reads = reads_of(action, gate);
        if (reads.size() > 1)
            return std::nullopt;
        if (reads.size() == 1)
            (reads[0].negated ? bases : twins).push_back(&action);
    }
    for (const pddl::Action *twin : twins)
        if (std::none_of(bases.begin(), bases.end(),
                         [&](const pddl::Action *base) { return is_twin(*base, *twin, gate); }))
            return std::nullopt;
    if (twins.empty() || in_goal_or_added(v, gate))
        return std::nullopt;
    for (const auto *p : v.problems)
        for (const auto &atom : p->init)
            if (atom.predicate == gate)
                return std::nullopt;
    std::set<std::string> untouchable;
    for (const pddl::Action *a : bases)
        untouchable.insert(a->name);
    for (const pddl::Action *a : twins)
        untouchable.insert(a->name);
    for (const auto &edits : v.edits) {
        for (const Edit *e : edits) {
            bool changes_gate = e->kind != EditKind::ADD_INIT &&
                                e->kind != EditKind::ADD_PREDICATE && predicate_of(*e) == gate;
            if (changes_gate || untouchable.count(schema_of(*e)))
                return std::nullopt;
        }
    }
    return twins;
}

std::string signature(const Edit &edit) {
    return edit_kind_name(edit.kind) + "|" + edit.action + "|" + edit.expression.to_string();
}

} // namespace

bool gated_twin_restricting(const DesignProblem &problem, int modification, bool robot) {
    const ModelView v = view_of(problem, robot);
    std::set<std::string> gates, fluents, fluent_edits;
    std::set<std::string> twins; // of the modification's gates
    for (const Edit *e : v.edits[modification]) {
        if (e->kind == EditKind::ADD_PREDICATE)
            continue;
        if (e->kind == EditKind::ADD_INIT) {
            if (auto found = twins_of_gate(v, predicate_of(*e))) {
                gates.insert(predicate_of(*e));
                for (const pddl::Action *a : *found)
                    twins.insert(a->name);
                continue;
            }
        }
        if (e->kind != EditKind::ADD_INIT && e->kind != EditKind::REMOVE_INIT &&
            e->kind != EditKind::ADD_EFFECT && e->kind != EditKind::REMOVE_EFFECT)
            return false;
        fluents.insert(predicate_of(*e));
        fluent_edits.insert(signature(*e));
    }
    if (gates.empty())
        return false;
    for (const std::string &f : fluents) {
        if (gates.count(f) || in_goal_or_added(v, f))
            return false;
        for (const auto &action : v.domain.actions)
            if (!reads_of(action, f).empty() && !twins.count(action.name))
                return false;
    }
    // Every modification of the family edits the fluents alike.
    for (const auto &edits : v.edits) {
        bool family = false;
        std::set<std::string> its;
        for (const Edit *e : edits) {
            std::string p = predicate_of(*e);
            if (fluents.count(p) && e->kind != EditKind::ADD_PREDICATE) {
                family = true;
                its.insert(signature(*e));
            }
            family = family || (e->kind == EditKind::ADD_INIT && gates.count(p));
        }
        if (family && its != fluent_edits)
            return false;
    }
    return true;
}

} // namespace envdesign::design
