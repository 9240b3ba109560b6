#include "pddl/name_scope.h"

#include <set>

namespace envdesign::pddl {
namespace {

const std::map<std::string, std::string> UNSUPPORTED_CONNECTIVES = {
    {"or", "'or' (disjunction)"},
    {"imply", "'imply' (implication)"},
    {"exists", "'exists' (existential quantification)"},
    {"forall", "'forall' (universal quantification)"},
    {"when", "'when' (conditional effects)"},
    {"assign", "'assign' (numeric fluents)"},
    {"decrease", "'decrease' (numeric fluents)"},
    {"scale-up", "'scale-up' (numeric fluents)"},
    {"scale-down", "'scale-down' (numeric fluents)"},
    {"<", "'<' (numeric comparison)"},
    {">", "'>' (numeric comparison)"},
    {"<=", "'<=' (numeric comparison)"},
    {">=", "'>=' (numeric comparison)"},
    {"preference", "'preference' (preferences)"},
};

std::vector<std::string> parse_type_spec(const SExpr &e,
                                         const std::map<std::string, std::string> *types) {
    std::vector<std::string> names;
    if (e.has_head("either")) {
        for (std::size_t i = 1; i < e.items.size(); ++i) {
            if (e.items[i].is_list)
                throw ParseError(e.items[i].location, "expected a type name inside 'either'");
            names.push_back(e.items[i].symbol);
        }
        if (names.empty())
            throw ParseError(e.location, "'either' needs at least one type");
    } else if (e.is_list) {
        throw ParseError(e.location, "expected a type name or (either ...)");
    } else {
        names.push_back(e.symbol);
    }
    if (types) {
        for (const auto &name : names)
            if (name != "object" && !types->count(name))
                throw ParseError(e.location, "undefined type '" + name + "'");
    }
    return names;
}

} // namespace

void reject_unsupported(const SExpr &e, const std::string &feature) {
    throw ParseError(e.location, feature + " is not supported (envdesign accepts STRIPS with "
                                           "typing, negative preconditions, equality and "
                                           "action costs)");
}

std::vector<TypedName> parse_typed_list(const std::vector<SExpr> &items, std::size_t begin,
                                        const std::string &kind,
                                        const std::map<std::string, std::string> *types) {
    std::vector<TypedName> result;
    std::size_t untyped_from = 0;
    std::set<std::string> seen;
    for (std::size_t i = begin; i < items.size(); ++i) {
        const SExpr &item = items[i];
        if (item.is_symbol("-")) {
            if (i + 1 >= items.size())
                throw ParseError(item.location, "'-' must be followed by a type");
            auto type_names = parse_type_spec(items[++i], types);
            // A '- type' with nothing before it types nothing: Fast Downward warns and goes
            // on ("a - t - u"); no domain of the IPC collection needs it.
            for (std::size_t j = untyped_from; j < result.size(); ++j)
                result[j].types = type_names;
            untyped_from = result.size();
            continue;
        }
        if (item.is_list)
            throw ParseError(item.location, "expected a " + kind + " name, found a list");
        // Names in a predicate declaration are placeholders; logistics00 declares (in ?obj ?obj).
        // A type may be listed twice (parse_types picks its parent; IPC 2006's Storage).
        if (!seen.insert(item.symbol).second && kind != "placeholder" && kind != "type")
            throw ParseError(item.location, "duplicate " + kind + " '" + item.symbol + "'");
        result.push_back({item.symbol, {"object"}, item.location});
    }
    return result;
}

void NameScope::add_variables(const std::vector<TypedName> &variables) {
    for (const auto &v : variables)
        names_[v.name] = v.types;
}

void NameScope::add_objects(const std::vector<TypedName> &objects) {
    for (const auto &o : objects)
        names_[o.name] = o.types;
}

const std::vector<std::string> *NameScope::types_of(const std::string &name) const {
    auto it = names_.find(name);
    return it == names_.end() ? nullptr : &it->second;
}

Atom NameScope::parse_atom(const SExpr &e, bool functions) const {
    if (!e.is_list || e.items.empty() || e.items[0].is_list)
        throw ParseError(e.location, "expected an atom '(predicate arg ...)' " + context_);
    Atom atom{e.items[0].symbol, {}, e.location};
    auto connective = UNSUPPORTED_CONNECTIVES.find(atom.predicate);
    if (connective != UNSUPPORTED_CONNECTIVES.end())
        reject_unsupported(e, connective->second);
    std::size_t arity = 2;
    if (atom.predicate != "=" || functions) {
        const auto &declared = functions ? domain_.functions : domain_.predicates;
        const Predicate *p = nullptr;
        for (const auto &candidate : declared)
            if (candidate.name == atom.predicate)
                p = &candidate;
        if (!p)
            throw ParseError(e.items[0].location, std::string("undefined ") +
                                                      (functions ? "function '" : "predicate '") +
                                                      atom.predicate + "' " + context_);
        arity = p->parameters.size();
    }
    if (e.items.size() - 1 != arity)
        throw ParseError(e.location, "'" + atom.predicate + "' takes " + std::to_string(arity) +
                                         " argument(s) but is given " +
                                         std::to_string(e.items.size() - 1) + " " + context_);
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr &arg = e.items[i];
        if (arg.is_list)
            throw ParseError(arg.location, "expected a variable or object name " + context_);
        if (!names_.count(arg.symbol)) {
            bool variable = !arg.symbol.empty() && arg.symbol[0] == '?';
            throw ParseError(
                arg.location,
                std::string(variable ? "undefined variable '" : "undefined object or constant '") +
                    arg.symbol + "' " + context_);
        }
        atom.args.push_back(arg.symbol);
    }
    return atom;
}

Literal NameScope::parse_literal(const SExpr &e) const {
    if (!e.has_head("not"))
        return {parse_atom(e), false};
    if (e.items.size() != 2)
        throw ParseError(e.location, "'not' takes exactly one argument " + context_);
    if (e.items[1].has_head("not")) // Fast Downward refuses it in an effect too
        throw ParseError(e.items[1].location, "'not' inside 'not' is allowed in a condition, "
                                              "not here " +
                                                  context_);
    return {parse_atom(e.items[1]), true};
}

std::vector<Literal> NameScope::parse_conjunction(const SExpr &e, const std::string &what) const {
    std::vector<Literal> result;
    add_condition(e, what, result);
    return result;
}

void NameScope::add_condition(const SExpr &e, const std::string &what,
                              std::vector<Literal> &out) const {
    // Negations are counted down to an atom or a conjunction, as Fast Downward's translator
    // puts conditions in negation normal form: (not (not L)) is L. No domain of the IPC
    // collection needs it; hand-written ones do.
    bool negated = false;
    const SExpr *c = &e;
    for (; c->has_head("not"); c = &c->items[1]) {
        if (c->items.size() != 2)
            throw ParseError(c->location, "'not' takes exactly one argument " + context_);
        negated = !negated;
    }
    if (!c->is_list)
        throw ParseError(c->location, "expected a " + what + " in parentheses " + context_);
    if (c->items.empty()) // the empty condition: true
        return;
    if (!c->has_head("and")) {
        out.push_back({parse_atom(*c), negated});
        return;
    }
    if (negated)
        reject_unsupported(*c, "'not' over 'and' (a disjunction)");
    for (std::size_t i = 1; i < c->items.size(); ++i)
        add_condition(c->items[i], what, out);
}

} // namespace envdesign::pddl
