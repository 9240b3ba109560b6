#include "design/model/lifted_key.h"

#include <sstream>

namespace envdesign::design {
namespace {

// Names may hold any character but space, parentheses and ';': prefix their length.
void name(std::ostream &out, const std::string &s) { out << s.size() << '#' << s; }

void write(std::ostream &out, const std::vector<pddl::TypedName> &names) {
    out << '[' << names.size();
    for (const auto &n : names) {
        name(out, n.name);
        out << '-' << n.types.size();
        for (const auto &t : n.types)
            name(out, t);
    }
    out << ']';
}

// As Atom::to_string and Literal::to_string write them, without a string of each.
void write(std::ostream &out, const pddl::Atom &a) {
    out << '(' << a.predicate;
    for (const auto &arg : a.args)
        out << ' ' << arg;
    out << ')';
}

void write(std::ostream &out, const pddl::Literal &l) {
    if (l.negated)
        out << "(not ";
    write(out, l.atom);
    if (l.negated)
        out << ')';
}

void write(std::ostream &out, const std::vector<pddl::Literal> &literals) {
    out << '[';
    for (const auto &l : literals) {
        write(out, l);
        out << ';';
    }
    out << ']';
}

void write(std::ostream &out, const std::vector<pddl::CostExpression> &costs) {
    out << '[';
    for (const auto &c : costs)
        out << c.constant << '+' << (c.function ? c.function->to_string() : "") << ';';
    out << ']';
}

void write(std::ostream &out, const std::vector<pddl::Predicate> &signatures) {
    out << '[';
    for (const auto &p : signatures) {
        name(out, p.name);
        write(out, p.parameters);
    }
    out << ']';
}

void write_domain(std::ostream &out, const pddl::Domain &d) {
    for (const auto &[type, parent] : d.type_parent) {
        name(out, type);
        name(out, parent);
    }
    write(out, d.constants);
    write(out, d.predicates);
    write(out, d.functions);
    for (const auto &a : d.actions) {
        out << "\n";
        name(out, a.name);
        write(out, a.parameters);
        write(out, a.precondition);
        write(out, a.effect);
        write(out, a.costs);
        write(out, a.secondary_costs);
    }
}

void write_problem(std::ostream &out, const pddl::Problem &p) {
    out << "\n";
    write(out, p.objects);
    for (const auto &a : p.init) {
        write(out, a);
        out << ';';
    }
    for (const auto &[term, value] : p.function_values) {
        write(out, term);
        out << '=' << value << ';';
    }
    write(out, p.goal);
    out << p.minimize_total_cost;
}

} // namespace

std::string lifted_text(const pddl::Domain &domain, const pddl::Problem &problem) {
    std::ostringstream out;
    write_domain(out, domain);
    write_problem(out, problem);
    return out.str();
}

TaskKey lifted_key(const pddl::Domain &domain, const pddl::Problem &problem) {
    return key_of_text(lifted_text(domain, problem));
}

} // namespace envdesign::design
