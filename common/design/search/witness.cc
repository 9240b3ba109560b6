#include "design/search/witness.h"

#include "design/behaviour/behaviour.h"
#include "design/search/gated_twins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

namespace envdesign::design {
namespace {

enum Side { ROBOT, HUMAN };
const char *const kPrefix[] = {"R|", "H|"};

// How a model's predicates are read: positively, negatively (preconditions and goals);
// which are fresh (declared by a modification), and which modifications mention each.
struct Uses {
    std::set<std::string> positive, negative, fresh;
    std::map<std::string, std::set<int>> mentioned_by;

    // Fresh and mentioned by one modification only: whatever it does with the predicate is
    // read by its own added preconditions alone.
    bool private_fresh(const std::string &predicate) const {
        auto it = mentioned_by.find(predicate);
        return fresh.count(predicate) && it != mentioned_by.end() && it->second.size() == 1;
    }

    void add(const pddl::Literal &l) { (l.negated ? negative : positive).insert(l.atom.predicate); }
};

struct SpecLiteral {
    std::string predicate;
    std::string atom; // "(p a b)", or "(p ?x)" for schema literals
    bool negated = false;
};

SpecLiteral literal_of(const pddl::SExpr &e) {
    SpecLiteral l;
    const pddl::SExpr *atom = &e;
    if (e.has_head("not") && e.items.size() == 2) {
        l.negated = true;
        atom = &e.items[1];
    }
    l.atom = atom->to_string();
    if (atom->is_list && !atom->items.empty() && !atom->items[0].is_list)
        l.predicate = atom->items[0].symbol;
    return l;
}

std::vector<Side> sides(Model model) {
    std::vector<Side> out;
    if (applies_to_robot(model))
        out.push_back(ROBOT);
    if (applies_to_human(model))
        out.push_back(HUMAN);
    return out;
}

std::string where(const Edit &edit) {
    const auto &l = edit.location;
    return l.file + ":" + std::to_string(l.line) + ":" + std::to_string(l.column);
}

std::string literal_key(Side side, bool negated, const std::string &atom) {
    return kPrefix[side] + std::string(negated ? "-|" : "+|") + atom;
}

// How each side's predicates are read: by its domain's preconditions, every task's goals and
// the modifications' added preconditions and goals; which are fresh, and who mentions each.
std::array<Uses, 2> predicate_uses(const DesignProblem &problem) {
    std::array<Uses, 2> uses;
    for (Side side : {ROBOT, HUMAN}) {
        const pddl::Domain &domain = side == ROBOT ? problem.robot_domain : problem.human_domain;
        for (const auto &action : domain.actions)
            for (const auto &l : action.precondition)
                uses[side].add(l);
        for (const auto &task : problem.tasks)
            for (const auto &l : (side == ROBOT ? task.robot_problem : task.human_problem).goal)
                uses[side].add(l);
    }
    for (int i = 0; i < static_cast<int>(problem.modifications.size()); ++i) {
        for (const auto &edit : problem.modifications[i].edits) {
            for (Side side : sides(edit.model)) {
                if (edit.kind != EditKind::REMOVE_ACTION)
                    uses[side].mentioned_by[literal_of(edit.expression).predicate].insert(i);
                if (edit.kind == EditKind::ADD_PRECONDITION || edit.kind == EditKind::ADD_GOAL) {
                    SpecLiteral l = literal_of(edit.expression);
                    (l.negated ? uses[side].negative : uses[side].positive).insert(l.predicate);
                }
                const pddl::Domain &base =
                    side == ROBOT ? problem.robot_domain : problem.human_domain;
                if (edit.kind == EditKind::ADD_PREDICATE && edit.expression.is_list &&
                    !edit.expression.items.empty() &&
                    !base.find_predicate(edit.expression.items[0].symbol))
                    uses[side].fresh.insert(edit.expression.items[0].symbol);
            }
        }
    }
    return uses;
}

struct EditClass {
    bool restricting = true;
    bool adding = false; // only adds plans (the mirror of the restricting rules)
};

// One edit of a model whose predicates are read as `u` says, by witness.h's rules.
EditClass classify_edit(const Edit &edit, const Uses &u) {
    SpecLiteral l = literal_of(edit.expression);
    bool fresh = u.private_fresh(l.predicate);
    bool positive = u.positive.count(l.predicate), negative = u.negative.count(l.predicate);
    switch (edit.kind) {
    case EditKind::ADD_INIT:
        return {fresh || !positive, !negative};
    case EditKind::REMOVE_INIT:
        return {fresh || !negative, !positive};
    case EditKind::REMOVE_GOAL:
    case EditKind::REMOVE_PRECONDITION:
        return {false, true};
    case EditKind::ADD_PREDICATE:
        return {true, true};
    case EditKind::ADD_EFFECT:
    case EditKind::REMOVE_EFFECT: {
        // Adding a delete or dropping an add leaves fewer atoms of the predicate in every
        // state reached; the opposite leaves more.
        bool fewer = l.negated == (edit.kind == EditKind::ADD_EFFECT);
        return {fresh || (fewer ? !negative : !positive), fewer ? !positive : !negative};
    }
    case EditKind::ADD_GOAL:
    case EditKind::ADD_PRECONDITION:
    case EditKind::REMOVE_ACTION:
        break;
    }
    return {};
}

} // namespace

// "(move c00 c10)" -> {"move", "c00", "c10"}
std::vector<std::string> words_of(const std::string &step) {
    std::string inner = step;
    std::replace(inner.begin(), inner.end(), '(', ' ');
    std::replace(inner.begin(), inner.end(), ')', ' ');
    std::istringstream in(inner);
    std::vector<std::string> words;
    for (std::string w; in >> w;)
        words.push_back(w);
    return words;
}

std::string ground_atom(const pddl::Atom &atom, const pddl::Action &action,
                        const std::vector<std::string> &arguments) {
    std::string out = "(" + atom.predicate;
    for (const auto &arg : atom.args) {
        std::string value = arg;
        for (std::size_t i = 0; i < action.parameters.size(); ++i)
            if (action.parameters[i].name == arg)
                value = arguments[i + 1];
        out += " " + value;
    }
    return out + ")";
}

TouchIndex::TouchIndex(const DesignProblem &problem) : problem_(problem) {
    const std::array<Uses, 2> uses = predicate_uses(problem);
    for (int side : {ROBOT, HUMAN})
        added_[side].resize(problem.modifications.size());
    for (int i = 0; i < static_cast<int>(problem.modifications.size()); ++i) {
        ModificationClass c;
        for (const auto &edit : problem.modifications[i].edits) {
            for (Side side : sides(edit.model)) {
                EditClass e = classify_edit(edit, uses[side]);
                index_edit(i, edit, side);
                if (edit.kind != EditKind::ADD_PREDICATE)
                    (side == ROBOT ? c.edits_robot : c.edits_human) = true;
                if (!e.restricting)
                    (side == ROBOT ? c.robot_restricting : c.human_restricting) = false;
                c.adding = c.adding && e.adding;
                if (!e.restricting && c.restricting) {
                    c.restricting = false;
                    c.why_not = edit_kind_name(edit.kind) + " " + edit.expression.to_string() +
                                " (" + where(edit) + ")";
                }
            }
        }
        // Gating (gated_twins.h) keeps c_R* from dropping, though not every plan valid: it
        // bounds the robot's cost, not the witnesses.
        if (!c.robot_restricting && gated_twin_restricting(problem, i, true))
            c.robot_restricting = true;
        if (!c.human_restricting && gated_twin_restricting(problem, i, false))
            c.human_restricting = true;
        classes_.push_back(c);
    }
}

void TouchIndex::index_edit(int modification, const Edit &edit, int side) {
    const std::string prefix = kPrefix[side];
    switch (edit.kind) {
    case EditKind::ADD_INIT: // touches a plan that needs the atom absent
    case EditKind::REMOVE_INIT:
        by_key_[literal_key(Side(side), edit.kind == EditKind::ADD_INIT,
                            literal_of(edit.expression).atom)]
            .push_back(modification);
        break;
    case EditKind::ADD_GOAL:
        (side == ROBOT ? every_robot_witness_ : every_human_witness_).push_back(modification);
        added_[side][modification].push_back({"", as_literal(edit.expression)});
        break;
    case EditKind::ADD_PRECONDITION:
        by_key_[prefix + "schema|" + edit.action].push_back(modification);
        added_[side][modification].push_back({edit.action, as_literal(edit.expression)});
        break;
    case EditKind::ADD_EFFECT:
    case EditKind::REMOVE_EFFECT:
        by_key_[prefix + "schema|" + edit.action].push_back(modification);
        break;
    case EditKind::REMOVE_ACTION:
        by_key_[edit.expression.is_list ? prefix + "act|" + edit.expression.to_string()
                                        : prefix + "schema|" + edit.expression.symbol]
            .push_back(modification);
        break;
    case EditKind::REMOVE_GOAL: // not restricting: restricting_only drops them anyway
    case EditKind::REMOVE_PRECONDITION:
    case EditKind::ADD_PREDICATE: // nothing a plan relies on
        break;
    }
}

void TouchIndex::add_key(const std::string &key, std::vector<int> &out) const {
    auto it = by_key_.find(key);
    if (it != by_key_.end())
        out.insert(out.end(), it->second.begin(), it->second.end());
}

const TouchIndex::PlanTouch &TouchIndex::plan_touch(int side, const Configuration &configuration,
                                                    int task,
                                                    const std::vector<std::string> &plan) const {
    std::string memo_key = std::to_string(side) + "|" + std::to_string(task) + "|";
    for (int m : configuration)
        if (!added_[side][m].empty())
            memo_key += std::to_string(m) + ",";
    for (const auto &step : plan)
        memo_key += step;
    auto [entry, fresh] = memo_.try_emplace(memo_key);
    if (!fresh)
        return entry->second;
    PlanTouch &out = entry->second;
    const DesignTask &t = problem_.tasks[task];
    const pddl::Domain &domain = side == ROBOT ? problem_.robot_domain : problem_.human_domain;
    std::string prefix = kPrefix[side];
    for (const auto &l : (side == ROBOT ? t.robot_problem : t.human_problem).goal)
        add_key(literal_key(Side(side), l.negated, l.atom.to_string()), out.mods);
    for (int m : configuration)
        for (const auto &added : added_[side][m])
            if (added.action.empty())
                add_key(
                    literal_key(Side(side), added.literal.negated, added.literal.atom.to_string()),
                    out.mods);
    for (const auto &step : plan) {
        std::vector<std::string> words = words_of(step);
        const pddl::Action *action = words.empty() ? nullptr : domain.find_action(words[0]);
        if (!action || action->parameters.size() + 1 != words.size()) {
            out.known = false; // a step this model does not have: say nothing
            return out;
        }
        add_key(prefix + "act|" + step, out.mods);
        add_key(prefix + "schema|" + action->name, out.mods);
        auto add_precondition = [&](const pddl::Literal &l) {
            if (l.atom.predicate != "=")
                add_key(literal_key(Side(side), l.negated, ground_atom(l.atom, *action, words)),
                        out.mods);
        };
        for (const auto &l : action->precondition)
            add_precondition(l);
        for (int m : configuration)
            for (const auto &added : added_[side][m])
                if (added.action == action->name)
                    add_precondition(added.literal);
    }
    return out;
}

WitnessTouch TouchIndex::touching(const Configuration &configuration, int task,
                                  const TaskExplicability &evaluation) const {
    WitnessTouch out;
    if (evaluation.status == ExplicabilityStatus::INEXPLICABLE)
        return out; // no plan: restricting modifications keep it so
    if (evaluation.status != ExplicabilityStatus::SOLVED || !evaluation.human_plan) {
        out.known = false;
        return out;
    }
    // COST_OPTIMAL with a finite worst case: a human-model edit that makes any optimal robot
    // plan invalid for people changes it, so on the human side every action of every
    // optimal plan is a witness (docs/design-search.md). Everywhere else `plan` is enough.
    const std::vector<std::string> *human_witness = &evaluation.plan;
    if (behaviour_of(problem_.weights.behaviour).every_optimal_action_witnesses &&
        std::isfinite(evaluation.human_plan_cost)) {
        if (!evaluation.optimal_actions) {
            out.known = false;
            return out;
        }
        human_witness = &*evaluation.optimal_actions;
    }
    std::vector<int> explicable;
    for (int side : {ROBOT, HUMAN}) {
        const PlanTouch &touch =
            plan_touch(side, configuration, task, side == ROBOT ? evaluation.plan : *human_witness);
        out.known = out.known && touch.known;
        explicable.insert(explicable.end(), touch.mods.begin(), touch.mods.end());
    }
    explicable.insert(explicable.end(), every_robot_witness_.begin(), every_robot_witness_.end());
    out.explicable = restricting_only(std::move(explicable), HUMAN);
    auto human = touching_human_plan(configuration, task, *evaluation.human_plan);
    out.known = out.known && human;
    if (human)
        out.human = std::move(*human);
    std::set_union(out.explicable.begin(), out.explicable.end(), out.human.begin(), out.human.end(),
                   std::back_inserter(out.all));
    return out;
}

std::optional<std::vector<int>>
TouchIndex::touching_human_plan(const Configuration &configuration, int task,
                                const std::vector<std::string> &plan) const {
    const PlanTouch &touch = plan_touch(HUMAN, configuration, task, plan);
    if (!touch.known)
        return std::nullopt;
    return restricting_only(touch.mods, HUMAN);
}

std::optional<std::vector<int>>
TouchIndex::touching_robot_plan(const Configuration &configuration, int task,
                                const std::vector<std::string> &plan) const {
    const PlanTouch &touch = plan_touch(ROBOT, configuration, task, plan);
    if (!touch.known)
        return std::nullopt;
    return restricting_only(touch.mods, ROBOT);
}

// Sorted, unique, restricting, with the add_goal modifications of `side`'s model (they
// touch every witness there).
std::vector<int> TouchIndex::restricting_only(std::vector<int> mods, int side) const {
    const std::vector<int> &every = side == ROBOT ? every_robot_witness_ : every_human_witness_;
    mods.insert(mods.end(), every.begin(), every.end());
    std::sort(mods.begin(), mods.end());
    mods.erase(std::unique(mods.begin(), mods.end()), mods.end());
    std::erase_if(mods, [&](int m) { return !classes_[m].restricting; });
    return mods;
}

} // namespace envdesign::design
