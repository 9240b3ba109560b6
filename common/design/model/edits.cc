#include "design/model/edits.h"

#include "pddl/name_scope.h"

#include <algorithm>
#include <cctype>

namespace envdesign::design {
namespace {

using pddl::Atom;
using pddl::Literal;
using pddl::ParseError;
using pddl::SExpr;

// Edits refer to the spec file, not to a position inside the quoted string.
void relocate(SExpr &e, const pddl::Location &where) {
    e.location = where;
    for (auto &item : e.items)
        relocate(item, where);
}

std::string context_of(const Edit &edit) { return "in edit " + edit_kind_name(edit.kind); }

bool same(const Literal &a, const Literal &b) { return a.negated == b.negated && a.atom == b.atom; }

bool contains(const std::vector<Literal> &list, const Literal &l) {
    return std::any_of(list.begin(), list.end(), [&](const Literal &x) { return same(x, l); });
}

// Removes `l` from `list`; in STRICT mode its absence is an error.
void remove_literal(std::vector<Literal> &list, const Literal &l, const Edit &edit, ApplyMode mode,
                    const std::string &where) {
    auto it = std::find_if(list.begin(), list.end(), [&](const Literal &x) { return same(x, l); });
    if (it != list.end())
        list.erase(it);
    else if (mode == ApplyMode::STRICT)
        throw NotPresentError(edit.location,
                              l.to_string() + " is not in " + where + " " + context_of(edit));
}

pddl::NameScope ground_scope(const pddl::Domain &domain, const pddl::Problem &problem,
                             const Edit &edit) {
    pddl::NameScope scope(domain, context_of(edit));
    scope.add_objects(domain.constants);
    scope.add_objects(problem.objects);
    return scope;
}

pddl::Action *find_action(pddl::Domain &domain, const Edit &edit, ApplyMode mode) {
    pddl::Action *action = domain.find_action(edit.action);
    if (!action && mode == ApplyMode::STRICT)
        throw ParseError(edit.location, "unknown action '" + edit.action + "' " + context_of(edit));
    return action;
}

pddl::Problem &need_problem(pddl::Problem *problem, const Edit &edit) {
    if (!problem)
        throw ParseError(edit.location,
                         "internal: " + edit_kind_name(edit.kind) + " needs a problem");
    return *problem;
}

void apply_init(const Edit &edit, const pddl::Domain &domain, pddl::Problem &problem,
                ApplyMode mode) {
    Atom atom = ground_scope(domain, problem, edit).parse_atom(edit.expression);
    if (atom.predicate == "=")
        throw ParseError(edit.location, "equality cannot be part of the initial state");
    auto it = std::find(problem.init.begin(), problem.init.end(), atom);
    if (edit.kind == EditKind::ADD_INIT) {
        if (it == problem.init.end())
            problem.init.push_back(atom);
    } else if (it != problem.init.end()) {
        problem.init.erase(it);
    } else if (mode == ApplyMode::STRICT) {
        throw NotPresentError(edit.location, atom.to_string() + " is not in the initial state " +
                                                 context_of(edit));
    }
}

void apply_goal(const Edit &edit, const pddl::Domain &domain, pddl::Problem &problem,
                ApplyMode mode) {
    Literal literal = ground_scope(domain, problem, edit).parse_literal(edit.expression);
    if (edit.kind == EditKind::REMOVE_GOAL)
        remove_literal(problem.goal, literal, edit, mode, "the goal");
    else if (!contains(problem.goal, literal))
        problem.goal.push_back(literal);
}

void apply_add_predicate(const Edit &edit, pddl::Domain &domain, ApplyMode mode) {
    const SExpr &e = edit.expression;
    if (!e.is_list || e.items.empty() || e.items[0].is_list)
        throw ParseError(edit.location,
                         "expected a declaration '(name ?x - type ...)' " + context_of(edit));
    pddl::Predicate p{e.items[0].symbol,
                      pddl::parse_typed_list(e.items, 1, "placeholder", &domain.type_parent),
                      edit.location};
    if (const pddl::Predicate *old = domain.find_predicate(p.name)) {
        if (mode == ApplyMode::STRICT || old->parameters.size() != p.parameters.size())
            throw ParseError(edit.location,
                             "predicate '" + p.name + "' is already declared " + context_of(edit));
        return;
    }
    domain.predicates.push_back(std::move(p));
}

Literal schema_literal(const Edit &edit, const pddl::Domain &domain, const pddl::Action &action) {
    pddl::NameScope scope(domain, context_of(edit) + " of action '" + action.name + "'");
    scope.add_objects(domain.constants);
    scope.add_variables(action.parameters);
    return scope.parse_literal(edit.expression);
}

void apply_schema_literal(const Edit &edit, pddl::Domain &domain, ApplyMode mode) {
    pddl::Action *action = find_action(domain, edit, mode);
    if (!action)
        return; // removed by another modification of this configuration
    Literal literal = schema_literal(edit, domain, *action);
    bool precondition =
        edit.kind == EditKind::ADD_PRECONDITION || edit.kind == EditKind::REMOVE_PRECONDITION;
    if (!precondition && literal.atom.predicate == "=")
        throw ParseError(edit.location, "an effect cannot change equality");
    auto &list = precondition ? action->precondition : action->effect;
    if (edit.kind == EditKind::REMOVE_PRECONDITION || edit.kind == EditKind::REMOVE_EFFECT) {
        remove_literal(list, literal, edit, mode,
                       "the " + std::string(precondition ? "precondition" : "effect") +
                           " of action '" + action->name + "'");
        return;
    }
    if (literal.negated && precondition)
        domain.requirements.insert(":negative-preconditions");
    if (!contains(list, literal))
        list.push_back(literal);
}

// One instance is removed by a static guard: (not (removed~move ?from ?to)) in the schema,
// (removed~move c00 c11) in the initial state. '~' keeps the name out of users' way.
void remove_instance(const Edit &edit, pddl::Domain &domain, pddl::Problem &problem,
                     ApplyMode mode) {
    const SExpr &e = edit.expression;
    if (e.items.empty() || e.items[0].is_list)
        throw ParseError(edit.location, "expected '(action object ...)' " + context_of(edit));
    Edit named = edit;
    named.action = e.items[0].symbol;
    pddl::Action *action = find_action(domain, named, mode);
    if (!action)
        return;
    if (e.items.size() - 1 != action->parameters.size())
        throw ParseError(edit.location, "'" + action->name + "' takes " +
                                            std::to_string(action->parameters.size()) +
                                            " argument(s) but is given " +
                                            std::to_string(e.items.size() - 1) + " " +
                                            context_of(edit));
    pddl::Predicate guard{"removed~" + action->name, action->parameters, edit.location};
    if (!domain.find_predicate(guard.name))
        domain.predicates.push_back(guard);
    pddl::NameScope scope = ground_scope(domain, problem, edit);
    SExpr instance = e;
    instance.items[0].symbol = guard.name;
    Atom removed = scope.parse_atom(instance);
    Literal pre{{guard.name, {}, edit.location}, true};
    for (const auto &p : action->parameters)
        pre.atom.args.push_back(p.name);
    if (!contains(action->precondition, pre))
        action->precondition.push_back(pre);
    domain.requirements.insert(":negative-preconditions");
    if (std::find(problem.init.begin(), problem.init.end(), removed) == problem.init.end())
        problem.init.push_back(removed);
}

void apply_remove_action(const Edit &edit, pddl::Domain &domain, pddl::Problem *problem,
                         ApplyMode mode) {
    if (edit.expression.is_list) {
        remove_instance(edit, domain, need_problem(problem, edit), mode);
        return;
    }
    Edit named = edit;
    named.action = edit.expression.symbol;
    if (find_action(domain, named, mode))
        std::erase_if(domain.actions,
                      [&](const pddl::Action &a) { return a.name == named.action; });
}

} // namespace

Edit parse_edit_text(EditKind kind, Model model, const std::string &action, const std::string &text,
                     const pddl::Location &where) {
    Edit edit{kind, model, action, {}, where};
    std::string trimmed = text;
    std::erase_if(trimmed, [](char c) { return c == '\n' || c == '\r'; });
    bool bare_name = kind == EditKind::REMOVE_ACTION &&
                     trimmed.find_first_of("() \t") == std::string::npos && !trimmed.empty();
    try {
        if (bare_name) {
            edit.expression.symbol = trimmed;
            std::transform(trimmed.begin(), trimmed.end(), edit.expression.symbol.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        } else {
            edit.expression = pddl::read_sexpr(text, where.file);
        }
    } catch (const ParseError &e) {
        throw ParseError(where,
                         "in edit " + edit_kind_name(kind) + ": '" + text + "': " + e.message());
    }
    relocate(edit.expression, where);
    std::transform(edit.action.begin(), edit.action.end(), edit.action.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return edit;
}

void apply_edit(const Edit &edit, pddl::Domain &domain, pddl::Problem *problem, ApplyMode mode) {
    switch (edit.kind) {
    case EditKind::ADD_INIT:
    case EditKind::REMOVE_INIT:
        return apply_init(edit, domain, need_problem(problem, edit), mode);
    case EditKind::ADD_GOAL:
    case EditKind::REMOVE_GOAL:
        return apply_goal(edit, domain, need_problem(problem, edit), mode);
    case EditKind::ADD_PREDICATE:
        return apply_add_predicate(edit, domain, mode);
    case EditKind::ADD_PRECONDITION:
    case EditKind::REMOVE_PRECONDITION:
    case EditKind::ADD_EFFECT:
    case EditKind::REMOVE_EFFECT:
        return apply_schema_literal(edit, domain, mode);
    case EditKind::REMOVE_ACTION:
        return apply_remove_action(edit, domain, problem, mode);
    }
}

bool applies_to_robot(Model model) { return model != Model::HUMAN; }
bool applies_to_human(Model model) { return model != Model::ROBOT; }

std::string edit_kind_name(EditKind kind) {
    switch (kind) {
    case EditKind::ADD_INIT:
        return "add_init";
    case EditKind::REMOVE_INIT:
        return "remove_init";
    case EditKind::ADD_GOAL:
        return "add_goal";
    case EditKind::REMOVE_GOAL:
        return "remove_goal";
    case EditKind::ADD_PREDICATE:
        return "add_predicate";
    case EditKind::ADD_PRECONDITION:
        return "add_precondition";
    case EditKind::REMOVE_PRECONDITION:
        return "remove_precondition";
    case EditKind::ADD_EFFECT:
        return "add_effect";
    case EditKind::REMOVE_EFFECT:
        return "remove_effect";
    case EditKind::REMOVE_ACTION:
        return "remove_action";
    }
    return "edit";
}

pddl::Literal as_literal(const pddl::SExpr &e) {
    pddl::Literal l;
    const pddl::SExpr *atom = &e;
    if (e.has_head("not") && e.items.size() == 2) {
        l.negated = true;
        atom = &e.items[1];
    }
    for (std::size_t i = 0; atom->is_list && i < atom->items.size(); ++i)
        (i == 0 ? l.atom.predicate : l.atom.args.emplace_back()) = atom->items[i].to_string();
    return l;
}

} // namespace envdesign::design
