#include "pddl/input_file.h"
#include "pddl/name_scope.h"
#include "pddl/parser.h"

#include <algorithm>
#include <map>
#include <set>

namespace envdesign::pddl {
namespace {

const std::set<std::string> SUPPORTED_REQUIREMENTS = {
    ":strips", ":typing", ":negative-preconditions", ":equality", ":action-costs"};
// Requirements beyond the fragment that Fast Downward's translator knows are accepted as
// declarations: a domain may declare more than it uses (IPC 2018's data-network-opt18-strips
// declares :adl), and what lies outside the fragment is refused where it is used, by name.
const std::set<std::string> DECLARED_ONLY_REQUIREMENTS = {":adl",
                                                          ":negation",
                                                          ":disjunctive-preconditions",
                                                          ":existential-preconditions",
                                                          ":universal-preconditions",
                                                          ":quantified-preconditions",
                                                          ":conditional-effects",
                                                          ":derived-predicates"};
// The rest of PDDL's labels, which Fast Downward refuses too.
const std::set<std::string> UNSUPPORTED_REQUIREMENTS = {":fluents",
                                                        ":numeric-fluents",
                                                        ":object-fluents",
                                                        ":durative-actions",
                                                        ":duration-inequalities",
                                                        ":continuous-effects",
                                                        ":timed-initial-literals",
                                                        ":preferences",
                                                        ":constraints"};

void parse_requirements(const SExpr &section, Domain &domain) {
    for (std::size_t i = 1; i < section.items.size(); ++i) {
        const SExpr &r = section.items[i];
        if (r.is_list)
            throw ParseError(r.location, "expected a requirement like ':strips'");
        if (DECLARED_ONLY_REQUIREMENTS.count(r.symbol))
            continue;
        if (UNSUPPORTED_REQUIREMENTS.count(r.symbol))
            throw ParseError(r.location, "requirement '" + r.symbol + "' is not supported");
        if (!SUPPORTED_REQUIREMENTS.count(r.symbol))
            throw ParseError(r.location, "unknown requirement '" + r.symbol + "'");
        domain.requirements.insert(r.symbol);
    }
}

// Whether `ancestor` is reached from `type` along any declared parent.
bool reaches(const std::map<std::string, std::vector<std::string>> &parents,
             const std::string &type, const std::string &ancestor, std::size_t depth = 0) {
    if (type == ancestor)
        return true;
    auto it = parents.find(type);
    if (it == parents.end() || depth > parents.size())
        return false;
    return std::any_of(it->second.begin(), it->second.end(), [&](const std::string &p) {
        return reaches(parents, p, ancestor, depth + 1);
    });
}

void parse_types(const SExpr &section, Domain &domain) {
    auto declared = parse_typed_list(section.items, 1, "type", nullptr);
    // A type may be listed more than once (IPC 2006's Storage: "area - object", then
    // "area crate - surface"), as Fast Downward reads it: its parent is the most specific
    // one listed, which must lie below every other (several unrelated parents would be
    // multiple inheritance, outside the fragment).
    std::map<std::string, std::vector<std::string>> parents;
    for (const auto &t : declared) {
        if (t.types.size() != 1)
            throw ParseError(t.location, "a type's parent cannot be an 'either' type");
        parents[t.name].push_back(t.types[0]);
    }
    for (const auto &t : declared) {
        if (domain.type_parent.count(t.name))
            continue;
        const auto &listed = parents.at(t.name);
        auto most_specific = std::find_if(listed.begin(), listed.end(), [&](const std::string &p) {
            return std::all_of(listed.begin(), listed.end(),
                               [&](const std::string &q) { return reaches(parents, p, q); });
        });
        if (most_specific == listed.end())
            throw ParseError(t.location, "type '" + t.name +
                                             "' is listed under unrelated parents '" + listed[0] +
                                             "' and '" + listed.back() + "'");
        domain.type_parent[t.name] = *most_specific;
    }
    // A parent that is never listed itself ("room hall - place") is a type below object,
    // as IPC domains assume.
    for (const auto &t : declared)
        domain.type_parent.emplace(t.types[0], "object");
    domain.type_parent.erase("object");
    for (const auto &[type, parent] : domain.type_parent) {
        std::string ancestor = parent;
        for (std::size_t depth = 0; ancestor != "object"; ++depth) {
            if (ancestor == type || depth > domain.type_parent.size())
                throw ParseError(section.location, "type '" + type + "' is its own ancestor");
            ancestor = domain.type_parent.at(ancestor);
        }
    }
}

bool same_types(const std::vector<TypedName> &a, const std::vector<TypedName> &b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const TypedName &x, const TypedName &y) { return x.types == y.types; });
}

std::vector<Predicate> parse_signatures(const SExpr &section, const Domain &domain,
                                        const std::string &kind) {
    std::vector<Predicate> result;
    std::set<std::string> seen;
    for (std::size_t i = 1; i < section.items.size(); ++i) {
        const SExpr &p = section.items[i];
        if (p.is_symbol("-")) { // a function's result type: "- number"
            ++i;
            continue;
        }
        if (!p.is_list || p.items.empty() || p.items[0].is_list)
            throw ParseError(p.location, "expected a " + kind + " declaration '(name ?x ...)'");
        const std::string &name = p.items[0].symbol;
        auto parameters = parse_typed_list(p.items, 1, "placeholder", &domain.type_parent);
        if (!seen.insert(name).second) {
            // Declared twice alike is harmless (Fast Downward reads any repeat); declared
            // twice otherwise is ambiguous (Fast Downward would take the last one silently).
            auto first = std::find_if(result.begin(), result.end(),
                                      [&](const Predicate &q) { return q.name == name; });
            if (same_types(first->parameters, parameters))
                continue;
            throw ParseError(p.location,
                             kind + " '" + name + "' is declared twice with different parameters");
        }
        result.push_back({name, std::move(parameters), p.location});
    }
    return result;
}

CostExpression parse_cost(const SExpr &e, const NameScope &scope) {
    if (e.items.size() != 3 || !e.items[1].has_head("total-cost"))
        reject_unsupported(e, "numeric effects other than (increase (total-cost) ...)");
    const SExpr &amount = e.items[2];
    CostExpression cost;
    if (amount.is_list) {
        cost.function = scope.parse_atom(amount, true);
        return cost;
    }
    try {
        std::size_t used = 0;
        cost.constant = std::stoi(amount.symbol, &used);
        if (used != amount.symbol.size() || cost.constant < 0)
            throw std::invalid_argument("not a non-negative integer");
    } catch (const std::exception &) {
        throw ParseError(amount.location,
                         "action cost '" + amount.symbol + "' is not a non-negative integer");
    }
    return cost;
}

void parse_effect(const SExpr &e, const NameScope &scope, Action &action) {
    if (!e.is_list)
        throw ParseError(e.location, "expected an effect in parentheses");
    if (e.items.empty())
        return;
    if (e.has_head("and")) {
        for (std::size_t i = 1; i < e.items.size(); ++i)
            parse_effect(e.items[i], scope, action);
    } else if (e.has_head("increase")) {
        action.costs.push_back(parse_cost(e, scope));
    } else {
        Literal l = scope.parse_literal(e);
        if (l.atom.predicate == "=")
            throw ParseError(e.location, "an effect cannot change equality");
        action.effect.push_back(l);
    }
}

Action parse_action(const SExpr &e, const Domain &domain) {
    if (e.items.size() < 2 || e.items[1].is_list)
        throw ParseError(e.location, "expected an action name after ':action'");
    Action action;
    action.name = e.items[1].symbol;
    action.location = e.location;
    NameScope scope(domain, "in action '" + action.name + "'");
    scope.add_objects(domain.constants);
    for (std::size_t i = 2; i + 1 < e.items.size(); i += 2) {
        const SExpr &key = e.items[i];
        const SExpr &value = e.items[i + 1];
        if (key.is_symbol(":parameters")) {
            if (!value.is_list)
                throw ParseError(value.location, "expected a parameter list");
            action.parameters = parse_typed_list(value.items, 0, "parameter", &domain.type_parent);
            scope.add_variables(action.parameters);
        } else if (key.is_symbol(":precondition")) {
            action.precondition = scope.parse_conjunction(value, "precondition");
        } else if (key.is_symbol(":effect")) {
            parse_effect(value, scope, action);
        } else {
            throw ParseError(key.location, "unknown action section '" + key.to_string() + "'");
        }
    }
    if (e.items.size() % 2 != 0)
        throw ParseError(e.items.back().location, "action section without a value");
    return action;
}

} // namespace

Domain parse_domain(const SExpr &define, const std::string &file) {
    if (!define.has_head("define") || define.items.size() < 2 ||
        !define.items[1].has_head("domain") || define.items[1].items.size() != 2)
        throw ParseError(define.location, "expected '(define (domain NAME) ...)'");
    Domain domain;
    domain.file = file;
    domain.name = define.items[1].items[1].symbol;
    // Declarations may come in any order (Fast Downward reads them so before the first action,
    // with a warning; after an action is harmless too): each is read in the order its
    // dependencies need.
    static const std::vector<std::string> DECLARATIONS = {":requirements", ":types", ":constants",
                                                          ":predicates", ":functions"};
    std::map<std::string, const SExpr *> declarations;
    std::vector<const SExpr *> actions;
    for (std::size_t i = 2; i < define.items.size(); ++i) {
        const SExpr &section = define.items[i];
        if (!section.is_list || section.items.empty() || section.items[0].is_list)
            throw ParseError(section.location,
                             "expected a domain section like '(:predicates ...)'");
        const std::string &head = section.items[0].symbol;
        if (head == ":action") {
            actions.push_back(&section);
        } else if (head == ":derived" || head == ":durative-action" || head == ":constraints") {
            reject_unsupported(section, "'" + head + "'");
        } else if (std::find(DECLARATIONS.begin(), DECLARATIONS.end(), head) ==
                   DECLARATIONS.end()) {
            throw ParseError(section.location, "unknown domain section '" + head + "'");
        } else if (!declarations.emplace(head, &section).second) {
            throw ParseError(section.location, "duplicate section '" + head + "'");
        }
    }
    for (const auto &head : DECLARATIONS) {
        auto found = declarations.find(head);
        if (found == declarations.end())
            continue;
        const SExpr &section = *found->second;
        if (head == ":requirements")
            parse_requirements(section, domain);
        else if (head == ":types")
            parse_types(section, domain);
        else if (head == ":constants")
            domain.constants = parse_typed_list(section.items, 1, "constant", &domain.type_parent);
        else if (head == ":predicates")
            domain.predicates = parse_signatures(section, domain, "predicate");
        else
            domain.functions = parse_signatures(section, domain, "function");
    }
    for (const SExpr *section : actions) {
        Action action = parse_action(*section, domain);
        if (domain.find_action(action.name))
            throw ParseError(section->location, "duplicate action '" + action.name + "'");
        domain.actions.push_back(std::move(action));
    }
    return domain;
}

Domain parse_domain_text(const std::string &text, const std::string &name) {
    return parse_domain(read_sexpr(text, name), name);
}

Domain parse_domain_file(const std::string &path) {
    return parse_domain_text(read_input_file(path), path);
}

} // namespace envdesign::pddl
