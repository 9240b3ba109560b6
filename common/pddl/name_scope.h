#pragma once
// What a name in an atom may refer to, and the checks every atom passes: the predicate
// exists, the arity matches, every argument is a known variable or object.

#include "pddl/sexpr.h"
#include "pddl/task.h"

#include <map>
#include <string>
#include <vector>

namespace envdesign::pddl {

class NameScope {
public:
    NameScope(const Domain &domain, std::string context)
        : domain_(domain), context_(std::move(context)) {}

    void add_variables(const std::vector<TypedName> &variables);
    void add_objects(const std::vector<TypedName> &objects);
    const std::vector<std::string> *types_of(const std::string &name) const;

    // (p arg ...) checked against the predicates (or, when `functions`, the functions).
    Atom parse_atom(const SExpr &e, bool functions = false) const;
    // An atom, (not atom), (= a b) or (not (= a b)): an effect's literal.
    Literal parse_literal(const SExpr &e) const;
    // A condition: (and ...) of literals, a single literal, or () for "true"; nested ands are
    // flattened and double negations cancelled.
    std::vector<Literal> parse_conjunction(const SExpr &e, const std::string &what) const;

private:
    void add_condition(const SExpr &e, const std::string &what, std::vector<Literal> &out) const;

    const Domain &domain_;
    std::string context_; // "in action 'move'" etc., for messages
    std::map<std::string, std::vector<std::string>> names_;
};

// Reads "a b - t c - (either t u) d" from items[begin..]; `kind` names them in messages.
// Duplicates are an error; undefined types are an error when domain types are given.
std::vector<TypedName> parse_typed_list(const std::vector<SExpr> &items, std::size_t begin,
                                        const std::string &kind,
                                        const std::map<std::string, std::string> *types);

// Throws "NAME is not supported" for the PDDL features outside our fragment.
[[noreturn]] void reject_unsupported(const SExpr &e, const std::string &feature);

} // namespace envdesign::pddl
