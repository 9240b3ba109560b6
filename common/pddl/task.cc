#include "pddl/task.h"

namespace envdesign::pddl {

std::string Atom::to_string() const {
    std::size_t size = predicate.size() + 2;
    for (const auto &arg : args)
        size += arg.size() + 1;
    std::string out;
    out.reserve(size); // one allocation: atoms are written by the million (lifted_key.h)
    out += '(';
    out += predicate;
    for (const auto &arg : args) {
        out += ' ';
        out += arg;
    }
    out += ')';
    return out;
}

std::string Literal::to_string() const {
    return negated ? "(not " + atom.to_string() + ")" : atom.to_string();
}

const Predicate *Domain::find_predicate(const std::string &name) const {
    for (const auto &p : predicates)
        if (p.name == name)
            return &p;
    return nullptr;
}

const Action *Domain::find_action(const std::string &name) const {
    for (const auto &a : actions)
        if (a.name == name)
            return &a;
    return nullptr;
}

Action *Domain::find_action(const std::string &name) {
    for (auto &a : actions)
        if (a.name == name)
            return &a;
    return nullptr;
}

} // namespace envdesign::pddl
