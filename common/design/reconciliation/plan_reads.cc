#include "design/reconciliation/plan_reads.h"

#include <algorithm>
#include <cctype>

namespace envdesign::design {

namespace {

std::vector<std::string> step_words(const std::string &step) {
    std::vector<std::string> words;
    std::string word;
    for (char c : step) {
        bool separator = c == '(' || c == ')' || std::isspace(static_cast<unsigned char>(c));
        if (!separator)
            word += c;
        else if (!word.empty())
            words.push_back(std::move(word)), word.clear();
    }
    if (!word.empty())
        words.push_back(std::move(word));
    return words;
}

// `atom` of `action` with its parameters replaced by the step's arguments (`words`).
pddl::Atom ground_in_step(const pddl::Atom &atom, const pddl::Action &action,
                          const std::vector<std::string> &words) {
    pddl::Atom ground{atom.predicate, {}, {}};
    for (const auto &arg : atom.args) {
        auto it = std::find_if(action.parameters.begin(), action.parameters.end(),
                               [&](const pddl::TypedName &p) { return p.name == arg; });
        ground.args.push_back(
            it == action.parameters.end() ? arg : words[1 + (it - action.parameters.begin())]);
    }
    return ground;
}

} // namespace

PlanReads plan_reads(const ModelPair &models, const std::vector<std::string> &plan) {
    PlanReads reads;
    std::set<pddl::Atom> added;
    for (const auto &step : plan) {
        std::vector<std::string> words = step_words(step);
        const pddl::Action *action =
            words.empty() ? nullptr : models.human_domain.find_action(words[0]);
        if (!action || action->parameters.size() + 1 != words.size())
            return {};
        reads.schemas.insert(action->name);
        for (const auto &l : action->precondition) {
            pddl::Atom ground = ground_in_step(l.atom, *action, words);
            if (!l.negated && !added.count(ground))
                reads.from_init.insert(ground);
            reads.atoms.insert(std::move(ground));
        }
        for (const auto &l : action->effect)
            if (!l.negated)
                added.insert(ground_in_step(l.atom, *action, words));
    }
    for (const auto &l : models.human_problem.goal) {
        if (!l.negated && !added.count(l.atom))
            reads.from_init.insert(l.atom);
        reads.atoms.insert(l.atom);
    }
    reads.known = true;
    return reads;
}

bool may_break(const ModelDifference &d, const PlanReads &reads) {
    if (!reads.known || d.kind == DifferenceKind::GOAL)
        return true;
    if (d.kind == DifferenceKind::INIT)
        return reads.atoms.count(d.literal.atom) > 0;
    return reads.schemas.count(d.action) > 0; // a schema's precondition, effect, or itself
}

} // namespace envdesign::design
