#include "design/reconciliation/model_differences.h"

#include <algorithm>
#include <map>
#include <set>

namespace envdesign::design {
namespace {

using Renaming = std::map<std::string, std::string>;

// Parameter name -> "?index" (to_positions) or the reverse.
Renaming parameter_renaming(const pddl::Action &action, bool to_positions) {
    Renaming r;
    for (std::size_t i = 0; i < action.parameters.size(); ++i) {
        std::string position = "?" + std::to_string(i);
        if (to_positions)
            r[action.parameters[i].name] = position;
        else
            r[position] = action.parameters[i].name;
    }
    return r;
}

pddl::Literal renamed(pddl::Literal literal, const Renaming &renaming) {
    for (auto &arg : literal.atom.args)
        if (auto it = renaming.find(arg); it != renaming.end())
            arg = it->second;
    return literal;
}

bool same_literal(const pddl::Literal &a, const pddl::Literal &b) {
    return a.negated == b.negated && a.atom == b.atom;
}

bool contains(const std::vector<pddl::Literal> &list, const pddl::Literal &l) {
    return std::any_of(list.begin(), list.end(),
                       [&](const pddl::Literal &x) { return same_literal(x, l); });
}

std::vector<pddl::Literal> as_literals(const std::vector<pddl::Atom> &atoms) {
    std::vector<pddl::Literal> out;
    for (const auto &a : atoms)
        out.push_back({a, false});
    return out;
}

std::string sign(bool robot_has) { return robot_has ? "+" : "-"; }

class Collector {
public:
    Collector(const ModelPair &m, bool relevant_only) : models_(m), relevant_only_(relevant_only) {
        // Only predicates some precondition or goal reads can change a plan's validity.
        for (const pddl::Domain *d : {&m.robot_domain, &m.human_domain})
            for (const auto &a : d->actions)
                for (const auto &l : a.precondition)
                    read_.insert(l.atom.predicate);
        for (const pddl::Problem *p : {&m.robot_problem, &m.human_problem})
            for (const auto &l : p->goal)
                read_.insert(l.atom.predicate);
    }

    std::vector<ModelDifference> run() {
        one_sided(DifferenceKind::INIT, "", as_literals(models_.robot_problem.init),
                  as_literals(models_.human_problem.init), "init", true);
        one_sided(DifferenceKind::GOAL, "", models_.robot_problem.goal, models_.human_problem.goal,
                  "goal", false);
        for (const auto &robot : models_.robot_domain.actions)
            if (const pddl::Action *human = models_.human_domain.find_action(robot.name))
                schema(robot, *human);
        for (bool robot_has : {true, false}) {
            const pddl::Domain &from = robot_has ? models_.robot_domain : models_.human_domain;
            const pddl::Domain &other = robot_has ? models_.human_domain : models_.robot_domain;
            for (const auto &a : from.actions) {
                if (other.find_action(a.name))
                    continue;
                ModelDifference d;
                d.kind = DifferenceKind::ACTION;
                d.robot_has = robot_has;
                d.action = a.name;
                d.text = sign(robot_has) + "action " + a.name;
                out_.push_back(std::move(d));
            }
        }
        return std::move(out_);
    }

private:
    // The literals of `robot` missing from `human` (robot_has), then the reverse; `readers`
    // false keeps them whatever their predicate (goal literals are read by definition).
    void one_sided(DifferenceKind kind, const std::string &action,
                   const std::vector<pddl::Literal> &robot, const std::vector<pddl::Literal> &human,
                   const std::string &label, bool only_read,
                   const std::vector<pddl::Literal> *robot_text = nullptr,
                   const std::vector<pddl::Literal> *human_text = nullptr) {
        for (bool robot_has : {true, false}) {
            const auto &from = robot_has ? robot : human;
            const auto &other = robot_has ? human : robot;
            const auto *text = robot_has ? robot_text : human_text;
            std::vector<pddl::Literal> seen;
            for (std::size_t i = 0; i < from.size(); ++i) {
                const pddl::Literal &l = from[i];
                if (contains(other, l) || contains(seen, l))
                    continue;
                if (only_read && relevant_only_ && !read_.count(l.atom.predicate))
                    continue;
                seen.push_back(l);
                std::string shown = (text ? (*text)[i] : l).to_string();
                std::string where = action.empty() ? "" : action + " ";
                out_.push_back(
                    {kind, robot_has, action, l, sign(robot_has) + label + " " + where + shown});
            }
        }
    }

    void schema(const pddl::Action &robot, const pddl::Action &human) {
        if (robot.parameters.size() != human.parameters.size())
            throw pddl::ParseError(human.location, "action '" + robot.name +
                                                       "' has different parameters in the "
                                                       "robot's and the human's model");
        Renaming rp = parameter_renaming(robot, true), hp = parameter_renaming(human, true);
        auto canonical = [](const std::vector<pddl::Literal> &ls, const Renaming &r) {
            std::vector<pddl::Literal> out;
            for (const auto &l : ls)
                out.push_back(renamed(l, r));
            return out;
        };
        auto effects = [](const std::vector<pddl::Literal> &ls, bool deletes) {
            std::vector<pddl::Literal> out;
            for (const auto &l : ls)
                if (l.negated == deletes)
                    out.push_back(l);
            return out;
        };
        one_sided(DifferenceKind::PRECONDITION, robot.name, canonical(robot.precondition, rp),
                  canonical(human.precondition, hp), "pre", false, &robot.precondition,
                  &human.precondition);
        for (bool deletes : {false, true}) {
            auto r = effects(robot.effect, deletes), h = effects(human.effect, deletes);
            one_sided(deletes ? DifferenceKind::DELETE_EFFECT : DifferenceKind::ADD_EFFECT,
                      robot.name, canonical(r, rp), canonical(h, hp), deletes ? "del" : "add", true,
                      &r, &h);
        }
    }

    const ModelPair &models_;
    bool relevant_only_;
    std::set<std::string> read_;
    std::vector<ModelDifference> out_;
};

// Declares in told's human model what `atom` needs and only the robot's model declares.
void declare(const pddl::Atom &atom, const ModelPair &models, ModelPair &told) {
    pddl::Domain &domain = told.human_domain;
    if (atom.predicate != "=" && !domain.find_predicate(atom.predicate))
        if (const pddl::Predicate *p = models.robot_domain.find_predicate(atom.predicate))
            domain.predicates.push_back(*p);
    auto named = [](const std::vector<pddl::TypedName> &names, const std::string &n) {
        return std::find_if(names.begin(), names.end(),
                            [&](const pddl::TypedName &t) { return t.name == n; });
    };
    for (const auto &arg : atom.args) {
        if (arg.empty() || arg[0] == '?' ||
            named(domain.constants, arg) != domain.constants.end() ||
            named(told.human_problem.objects, arg) != told.human_problem.objects.end())
            continue;
        const auto &objects = models.robot_problem.objects;
        const auto &constants = models.robot_domain.constants;
        if (auto it = named(objects, arg); it != objects.end())
            told.human_problem.objects.push_back(*it);
        else if (auto c = named(constants, arg); c != constants.end())
            domain.constants.push_back(*c);
    }
}

void toggle(std::vector<pddl::Literal> &list, const pddl::Literal &l, bool add) {
    if (add) {
        if (!contains(list, l))
            list.push_back(l);
    } else {
        list.erase(std::remove_if(list.begin(), list.end(),
                                  [&](const pddl::Literal &x) { return same_literal(x, l); }),
                   list.end());
    }
}

void apply_action(const ModelDifference &d, const ModelPair &models, ModelPair &told) {
    auto &actions = told.human_domain.actions;
    if (!d.robot_has) {
        actions.erase(std::remove_if(actions.begin(), actions.end(),
                                     [&](const pddl::Action &a) { return a.name == d.action; }),
                      actions.end());
        return;
    }
    const pddl::Action *robot = models.robot_domain.find_action(d.action);
    if (!robot || told.human_domain.find_action(d.action))
        return;
    for (const auto *list : {&robot->precondition, &robot->effect})
        for (const auto &l : *list)
            declare(l.atom, models, told);
    actions.push_back(*robot);
}

} // namespace

std::vector<ModelDifference> model_differences(const ModelPair &models, bool relevant_only) {
    return Collector(models, relevant_only).run();
}

void apply_difference(const ModelDifference &d, const ModelPair &models, ModelPair &told) {
    switch (d.kind) {
    case DifferenceKind::INIT: {
        auto &init = told.human_problem.init;
        auto it = std::find(init.begin(), init.end(), d.literal.atom);
        if (d.robot_has && it == init.end()) {
            declare(d.literal.atom, models, told);
            init.push_back(d.literal.atom);
        } else if (!d.robot_has && it != init.end()) {
            init.erase(it);
        }
        return;
    }
    case DifferenceKind::GOAL:
        if (d.robot_has)
            declare(d.literal.atom, models, told);
        toggle(told.human_problem.goal, d.literal, d.robot_has);
        return;
    case DifferenceKind::ACTION:
        apply_action(d, models, told);
        return;
    default:
        break;
    }
    pddl::Action *human = told.human_domain.find_action(d.action);
    if (!human)
        return; // the schema itself is not in the human's model
    pddl::Literal l = renamed(d.literal, parameter_renaming(*human, false));
    if (d.robot_has)
        declare(l.atom, models, told);
    auto &list = d.kind == DifferenceKind::PRECONDITION ? human->precondition : human->effect;
    toggle(list, l, d.robot_has);
}

ModelPair told_models(const ModelPair &models, const std::vector<ModelDifference> &differences,
                      const std::vector<int> &chosen) {
    ModelPair told = models;
    for (int i : chosen)
        apply_difference(differences[i], models, told);
    return told;
}

ModelPair told_human_model(const ModelPair &models, const std::vector<ModelDifference> &differences,
                           const std::vector<int> &chosen) {
    ModelPair told;
    told.human_domain = models.human_domain;
    told.human_problem = models.human_problem;
    for (int i : chosen)
        apply_difference(differences[i], models, told);
    return told;
}

} // namespace envdesign::design
