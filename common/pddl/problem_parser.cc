#include "pddl/input_file.h"
#include "pddl/name_scope.h"
#include "pddl/parser.h"

#include <map>
#include <set>

namespace envdesign::pddl {
namespace {

int parse_function_value(const SExpr &e) {
    try {
        std::size_t used = 0;
        int value = std::stoi(e.symbol, &used);
        if (!e.is_list && used == e.symbol.size() && value >= 0)
            return value;
    } catch (const std::exception &) {
    }
    throw ParseError(e.location,
                     "function value '" + e.to_string() + "' is not a non-negative integer");
}

void parse_init(const SExpr &section, const NameScope &scope, Problem &problem) {
    // Atoms listed as false: the closed world makes them redundant, but they must not
    // contradict an atom listed as true (Fast Downward reads both the same way).
    std::map<Atom, bool> listed;
    for (std::size_t i = 1; i < section.items.size(); ++i) {
        const SExpr &e = section.items[i];
        if (e.has_head("=")) {
            if (e.items.size() != 3 || !e.items[1].is_list)
                throw ParseError(e.location, "expected '(= (function arg ...) VALUE)' in :init");
            Atom f = scope.parse_atom(e.items[1], true);
            int value = parse_function_value(e.items[2]);
            auto [it, inserted] = problem.function_values.emplace(f, value);
            if (!inserted && it->second != value) // the same value twice is harmless
                throw ParseError(e.location, "conflicting values " + std::to_string(it->second) +
                                                 " and " + std::to_string(value) + " for " +
                                                 f.to_string());
            continue;
        }
        if (e.has_head("at") && e.items.size() == 3 && e.items[2].is_list)
            reject_unsupported(e, "a timed initial literal '(at TIME FACT)'");
        bool negated = e.has_head("not");
        if (negated && e.items.size() != 2)
            throw ParseError(e.location, "'not' takes exactly one argument in :init");
        Atom atom = scope.parse_atom(negated ? e.items[1] : e);
        auto [it, inserted] = listed.emplace(atom, !negated);
        if (!inserted && it->second == negated)
            throw ParseError(e.location, atom.to_string() + " is listed as both true and false");
        if (inserted && !negated) // repeated atoms are harmless; keep the first
            problem.init.push_back(atom);
    }
}

void parse_metric(const SExpr &section, Problem &problem) {
    if (section.items.size() != 3 || !section.items[1].is_symbol("minimize") ||
        !section.items[2].has_head("total-cost") || section.items[2].items.size() != 1)
        reject_unsupported(section, "a metric other than (:metric minimize (total-cost))");
    problem.minimize_total_cost = true;
}

} // namespace

Problem parse_problem(const SExpr &define, const std::string &file, const Domain &domain,
                      const std::string &other_domain_name) {
    if (!define.has_head("define") || define.items.size() < 2 ||
        !define.items[1].has_head("problem") || define.items[1].items.size() != 2)
        throw ParseError(define.location, "expected '(define (problem NAME) ...)'");
    Problem problem;
    problem.file = file;
    problem.name = define.items[1].items[1].symbol;
    NameScope scope(domain, "in problem '" + problem.name + "'");
    scope.add_objects(domain.constants);
    std::set<std::string> sections_seen;
    for (std::size_t i = 2; i < define.items.size(); ++i) {
        const SExpr &section = define.items[i];
        if (!section.is_list || section.items.empty() || section.items[0].is_list)
            throw ParseError(section.location, "expected a problem section like '(:init ...)'");
        const std::string &head = section.items[0].symbol;
        if (!sections_seen.insert(head).second)
            throw ParseError(section.location, "duplicate section '" + head + "'");
        if (head == ":domain") {
            if (section.items.size() != 2 || section.items[1].is_list)
                throw ParseError(section.location, "expected '(:domain NAME)'");
            problem.domain_name = section.items[1].symbol;
            if (problem.domain_name != domain.name &&
                (other_domain_name.empty() || problem.domain_name != other_domain_name))
                throw ParseError(section.items[1].location,
                                 "problem is for domain '" + problem.domain_name +
                                     "' but the domain file defines '" + domain.name + "'");
        } else if (head == ":requirements") {
            continue; // the domain's requirements govern
        } else if (head == ":objects") {
            auto objects = parse_typed_list(section.items, 1, "object", &domain.type_parent);
            for (const auto &o : objects) {
                bool is_constant = false;
                for (const auto &c : domain.constants)
                    is_constant |= c.name == o.name;
                if (!is_constant) // IPC problems often repeat the domain's constants
                    problem.objects.push_back(o);
            }
            scope.add_objects(problem.objects);
        } else if (head == ":init") {
            parse_init(section, scope, problem);
        } else if (head == ":goal") {
            if (section.items.size() != 2)
                throw ParseError(section.location, "expected exactly one goal formula");
            problem.goal = scope.parse_conjunction(section.items[1], "goal");
        } else if (head == ":metric") {
            parse_metric(section, problem);
        } else if (head == ":constraints") {
            reject_unsupported(section, "':constraints'");
        } else {
            throw ParseError(section.location, "unknown problem section '" + head + "'");
        }
    }
    if (!sections_seen.count(":goal"))
        throw ParseError(define.location, "problem '" + problem.name + "' has no :goal");
    return problem;
}

Problem parse_problem_text(const std::string &text, const std::string &name, const Domain &domain,
                           const std::string &other_domain_name) {
    return parse_problem(read_sexpr(text, name), name, domain, other_domain_name);
}

Problem parse_problem_file(const std::string &path, const Domain &domain,
                           const std::string &other_domain_name) {
    return parse_problem_text(read_input_file(path), path, domain, other_domain_name);
}

} // namespace envdesign::pddl
