#pragma once
// Overview: the lifted PDDL task, as written by the user.
//
// Domain and Problem keep names, types and source locations; nothing here is grounded.
// All names are lower case. Variables keep their '?'. The grounder (ground/) turns a
// Domain + Problem into an integer GroundTask; the design engine edits these structures
// (add a precondition, remove an init atom) before grounding.

#include "pddl/parse_error.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace envdesign::pddl {

// A name with its declared type: "?x - block", "a - (either truck car)".
struct TypedName {
    std::string name;
    std::vector<std::string> types = {"object"}; // more than one: (either ...)
    Location location;
};

// (p a ?x); also (= ?x ?y) with predicate "=".
struct Atom {
    std::string predicate;
    std::vector<std::string> args; // "?var" or an object/constant name
    Location location;

    std::string to_string() const;
    bool operator<(const Atom &o) const {
        return predicate != o.predicate ? predicate < o.predicate : args < o.args;
    }
    bool operator==(const Atom &o) const { return predicate == o.predicate && args == o.args; }
};

struct Literal {
    Atom atom;
    bool negated = false;

    std::string to_string() const;
};

// The cost an action adds to total-cost: a number, or a static function term.
struct CostExpression {
    int constant = 0;
    std::optional<Atom> function; // (travel-slow ?f1 ?f2)
};

struct Action {
    std::string name;
    std::vector<TypedName> parameters;
    std::vector<Literal> precondition; // a conjunction
    std::vector<Literal> effect;       // negated = delete
    std::vector<CostExpression> costs; // summed; empty = no cost given
    // A second cost, minimised among plans of least `costs` (the design engine's compiled
    // task: human cost first, robot cost second). Not written in PDDL; empty = 0.
    std::vector<CostExpression> secondary_costs;
    Location location;
};

struct Predicate {
    std::string name;
    std::vector<TypedName> parameters;
    Location location;
};

struct Domain {
    std::string name;
    std::string file;
    std::set<std::string> requirements;
    std::map<std::string, std::string> type_parent; // every declared type -> its parent
    std::vector<TypedName> constants;
    std::vector<Predicate> predicates;
    std::vector<Predicate> functions; // numeric functions, total-cost included
    std::vector<Action> actions;

    const Predicate *find_predicate(const std::string &name) const;
    const Action *find_action(const std::string &name) const;
    Action *find_action(const std::string &name);
};

struct Problem {
    std::string name;
    std::string file;
    std::string domain_name;
    std::vector<TypedName> objects;
    std::vector<Atom> init;
    std::map<Atom, int> function_values; // (= (travel-slow n0 n1) 6)
    std::vector<Literal> goal;           // a conjunction
    bool minimize_total_cost = false;    // (:metric minimize (total-cost))
};

} // namespace envdesign::pddl
