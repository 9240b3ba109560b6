#include "design/model/compilation.h"

#include <algorithm>
#include <map>
#include <utility>

namespace envdesign::design {
namespace {

using pddl::ParseError;
using Renaming = std::map<std::string, std::string>; // variable -> variable

pddl::Atom renamed(const pddl::Atom &atom, const std::string &prefix, const Renaming &vars) {
    pddl::Atom out = atom;
    if (atom.predicate != "=")
        out.predicate = prefix + atom.predicate;
    for (auto &arg : out.args)
        if (auto it = vars.find(arg); it != vars.end())
            arg = it->second;
    return out;
}

void append(std::vector<pddl::Literal> &to, const std::vector<pddl::Literal> &from,
            const std::string &prefix, const Renaming &vars) {
    for (const auto &l : from)
        to.push_back({renamed(l.atom, prefix, vars), l.negated});
}

// The cost a model charges for an action: its :action-costs when its problem has a metric,
// otherwise 1 (the grounder's unit cost).
std::vector<pddl::CostExpression> model_cost(const pddl::Action &action, bool metric,
                                             const std::string &prefix, const Renaming &vars) {
    if (!metric)
        return {pddl::CostExpression{1, std::nullopt}};
    std::vector<pddl::CostExpression> costs;
    for (const auto &c : action.costs) {
        pddl::CostExpression out{c.constant, std::nullopt};
        if (c.function)
            out.function = renamed(*c.function, prefix, vars);
        costs.push_back(out);
    }
    return costs;
}

void merge_types(const pddl::Domain &human, pddl::Domain &out) {
    for (const auto &[type, parent] : human.type_parent) {
        auto [it, inserted] = out.type_parent.emplace(type, parent);
        if (!inserted && it->second != parent)
            throw ParseError({human.file, 0, 0}, "type '" + type + "' has parent '" + parent +
                                                     "' in the human's model but '" + it->second +
                                                     "' in the robot's");
    }
}

// Adds `names` to `out`; a name already there must have the same type.
void merge_names(const std::vector<pddl::TypedName> &names, std::vector<pddl::TypedName> &out,
                 const std::string &what) {
    for (const auto &n : names) {
        bool found = false;
        for (const auto &o : out) {
            if (o.name != n.name)
                continue;
            found = true;
            if (o.types != n.types)
                throw ParseError(n.location, what + " '" + n.name +
                                                 "' has different types in the robot's and the "
                                                 "human's model");
        }
        if (!found)
            out.push_back(n);
    }
}

void add_signatures(const std::vector<pddl::Predicate> &from, const std::string &prefix,
                    std::vector<pddl::Predicate> &to) {
    for (const auto &p : from)
        if (p.name != "total-cost")
            to.push_back({prefix + p.name, p.parameters, p.location});
}

Renaming parameter_renaming(const pddl::Action &robot, const pddl::Action &human) {
    if (robot.parameters.size() != human.parameters.size())
        throw ParseError(human.location, "action '" + human.name + "' has " +
                                             std::to_string(human.parameters.size()) +
                                             " parameter(s) in the human's model but " +
                                             std::to_string(robot.parameters.size()) +
                                             " in the robot's");
    Renaming vars;
    for (std::size_t i = 0; i < robot.parameters.size(); ++i) {
        if (robot.parameters[i].types != human.parameters[i].types)
            throw ParseError(human.parameters[i].location,
                             "parameter " + std::to_string(i + 1) + " of action '" + human.name +
                                 "' has a different type in the human's model than in the robot's");
        vars[human.parameters[i].name] = robot.parameters[i].name;
    }
    return vars;
}

pddl::Action compile_action(const pddl::Action &robot, const pddl::Action &human,
                            const ModelPair &models) {
    Renaming vars = parameter_renaming(robot, human);
    pddl::Action out;
    out.name = robot.name;
    out.parameters = robot.parameters;
    out.location = robot.location;
    append(out.precondition, robot.precondition, "r-", {});
    append(out.precondition, human.precondition, "h-", vars);
    append(out.effect, robot.effect, "r-", {});
    append(out.effect, human.effect, "h-", vars);
    out.costs = model_cost(human, models.human_problem.minimize_total_cost, "h-", vars);
    out.secondary_costs = model_cost(robot, models.robot_problem.minimize_total_cost, "r-", {});
    return out;
}

pddl::Domain compile_domain(const ModelPair &models) {
    const pddl::Domain &robot = models.robot_domain;
    const pddl::Domain &human = models.human_domain;
    pddl::Domain out;
    out.name = "explicable-" + robot.name;
    out.file = robot.file;
    out.requirements = robot.requirements;
    out.requirements.insert(human.requirements.begin(), human.requirements.end());
    out.requirements.insert(":action-costs");
    out.type_parent = robot.type_parent;
    merge_types(human, out);
    out.constants = robot.constants;
    merge_names(human.constants, out.constants, "constant");
    add_signatures(robot.predicates, "r-", out.predicates);
    add_signatures(human.predicates, "h-", out.predicates);
    out.functions.push_back({"total-cost", {}, {}});
    add_signatures(robot.functions, "r-", out.functions);
    add_signatures(human.functions, "h-", out.functions);
    for (const auto &action : robot.actions)
        if (const pddl::Action *h = human.find_action(action.name))
            out.actions.push_back(compile_action(action, *h, models));
    return out;
}

pddl::Problem compile_problem(const ModelPair &models, const pddl::Domain &domain) {
    const pddl::Problem &robot = models.robot_problem;
    const pddl::Problem &human = models.human_problem;
    pddl::Problem out;
    out.name = "explicable-" + robot.name;
    out.file = robot.file;
    out.domain_name = domain.name;
    out.objects = robot.objects;
    merge_names(human.objects, out.objects, "object");
    std::erase_if(out.objects, [&](const pddl::TypedName &o) {
        for (const auto &c : domain.constants)
            if (c.name == o.name)
                return true;
        return false;
    });
    for (const auto &a : robot.init)
        out.init.push_back(renamed(a, "r-", {}));
    for (const auto &a : human.init)
        out.init.push_back(renamed(a, "h-", {}));
    for (const auto &[term, value] : robot.function_values)
        if (term.predicate != "total-cost")
            out.function_values[renamed(term, "r-", {})] = value;
    for (const auto &[term, value] : human.function_values)
        if (term.predicate != "total-cost")
            out.function_values[renamed(term, "h-", {})] = value;
    append(out.goal, robot.goal, "r-", {});
    append(out.goal, human.goal, "h-", {});
    out.minimize_total_cost = true;
    return out;
}

// The constant part of a cost and its function terms, sorted.
std::pair<int, std::vector<pddl::Atom>> split_cost(const std::vector<pddl::CostExpression> &costs) {
    std::pair<int, std::vector<pddl::Atom>> out{0, {}};
    for (const auto &c : costs) {
        out.first += c.constant;
        if (c.function)
            out.second.push_back(*c.function);
    }
    std::sort(out.second.begin(), out.second.end());
    return out;
}

// Whether every action both models have costs people at least what it costs the robot
// (`exactly`: just what it costs the robot), in every instance.
bool human_costs_relate(const pddl::Domain &robot_domain, const pddl::Problem &robot_problem,
                        const pddl::Domain &human_domain, const pddl::Problem &human_problem,
                        bool exactly) {
    for (const auto &robot : robot_domain.actions) {
        const pddl::Action *human = human_domain.find_action(robot.name);
        if (!human || human->parameters.size() != robot.parameters.size())
            continue; // not in P_mod (a mismatch is compile_explicable's error to report)
        Renaming vars;
        for (std::size_t i = 0; i < robot.parameters.size(); ++i)
            vars[human->parameters[i].name] = robot.parameters[i].name;
        auto [robot_constant, robot_terms] =
            split_cost(model_cost(robot, robot_problem.minimize_total_cost, "", {}));
        auto [human_constant, human_terms] =
            split_cost(model_cost(*human, human_problem.minimize_total_cost, "", vars));
        if (human_constant < robot_constant || human_terms != robot_terms ||
            (exactly && human_constant != robot_constant))
            return false;
        // The same terms cost the same only where both problems give them the same values.
        if (!robot_terms.empty() && robot_problem.function_values != human_problem.function_values)
            return false;
    }
    return true;
}

} // namespace

bool human_costs_dominate(const pddl::Domain &robot_domain, const pddl::Problem &robot_problem,
                          const pddl::Domain &human_domain, const pddl::Problem &human_problem) {
    return human_costs_relate(robot_domain, robot_problem, human_domain, human_problem, false);
}

bool costs_agree(const ModelPair &models) {
    return human_costs_relate(models.robot_domain, models.robot_problem, models.human_domain,
                              models.human_problem, true);
}

std::string robot_copy(const std::string &name) { return "r-" + name; }
std::string human_copy(const std::string &name) { return "h-" + name; }

CompiledTask compile_explicable(const ModelPair &models) {
    CompiledTask out;
    out.domain = compile_domain(models);
    out.problem = compile_problem(models, out.domain);
    return out;
}

} // namespace envdesign::design
