#include "validate/plan_validator.h"

#include "pddl/input_file.h"
#include "pddl/sexpr.h"

#include <map>
#include <set>
#include <sstream>

namespace envdesign::validate {
namespace {

using Binding = std::map<std::string, std::string>;

std::string ground_atom(const pddl::Atom &atom, const Binding &binding) {
    std::string out = "(" + atom.predicate;
    for (const auto &arg : atom.args) {
        auto it = binding.find(arg);
        out += " " + (it == binding.end() ? arg : it->second);
    }
    return out + ")";
}

std::string resolve(const std::string &arg, const Binding &binding) {
    auto it = binding.find(arg);
    return it == binding.end() ? arg : it->second;
}

class Simulator {
public:
    Simulator(const pddl::Domain &domain, const pddl::Problem &problem)
        : domain_(domain), problem_(problem) {
        for (const auto &atom : problem.init)
            state_.insert(ground_atom(atom, {}));
        for (const auto &c : domain.constants)
            object_types_[c.name] = c.types;
        for (const auto &o : problem.objects)
            object_types_[o.name] = o.types;
    }

    // Returns an error message, or "" if the step applied.
    std::string apply(const std::string &step_text) {
        pddl::SExpr step;
        try {
            step = pddl::read_sexpr(step_text, "plan");
        } catch (const pddl::ParseError &e) {
            return "'" + step_text + "' is not an action: " + e.message();
        }
        if (step.items.empty() || step.items[0].is_list)
            return "'" + step_text + "' is not an action";
        const pddl::Action *action = domain_.find_action(step.items[0].symbol);
        if (!action)
            return "unknown action '" + step.items[0].symbol + "'";
        if (step.items.size() - 1 != action->parameters.size())
            return "'" + action->name + "' takes " + std::to_string(action->parameters.size()) +
                   " arguments";
        Binding binding;
        for (std::size_t i = 0; i < action->parameters.size(); ++i) {
            const std::string &object = step.items[i + 1].symbol;
            if (!has_type(object, action->parameters[i].types))
                return "'" + object + "' is not an object of the type of " +
                       action->parameters[i].name;
            binding[action->parameters[i].name] = object;
        }
        for (const auto &l : action->precondition) {
            if (!holds(l, binding))
                return "precondition " + l.to_string() + " of " + step.to_string() +
                       " does not hold";
        }
        long long cost = 1; // without the metric every action costs 1
        if (problem_.minimize_total_cost) {
            cost = 0;
            if (std::string missing = step_cost(*action, binding, cost); !missing.empty())
                return "the problem gives no value for " + missing + ", a cost of " +
                       step.to_string() + ", so it is not applicable";
        }
        for (const auto &l : action->effect)
            if (l.negated)
                state_.erase(ground_atom(l.atom, binding));
        for (const auto &l : action->effect)
            if (!l.negated)
                state_.insert(ground_atom(l.atom, binding));
        cost_ += cost;
        return "";
    }

    bool holds(const pddl::Literal &l, const Binding &binding) const {
        bool truth = l.atom.predicate == "="
                         ? resolve(l.atom.args[0], binding) == resolve(l.atom.args[1], binding)
                         : state_.count(ground_atom(l.atom, binding)) > 0;
        return truth != l.negated;
    }

    long long cost() const { return cost_; }

private:
    bool has_type(const std::string &object, const std::vector<std::string> &types) const {
        auto it = object_types_.find(object);
        if (it == object_types_.end())
            return false;
        for (std::string t : it->second) {
            for (int depth = 0; depth < 1000; ++depth) {
                for (const auto &wanted : types)
                    if (t == wanted || wanted == "object")
                        return true;
                auto parent = domain_.type_parent.find(t);
                if (parent == domain_.type_parent.end())
                    break;
                t = parent->second;
            }
        }
        return false;
    }

    // The step's cost into `cost`; returns the first term the problem gives no value for
    // ("" if none), which makes the step inapplicable, as the grounder has it.
    std::string step_cost(const pddl::Action &action, const Binding &binding,
                          long long &cost) const {
        for (const auto &c : action.costs) {
            cost += c.constant;
            if (!c.function)
                continue;
            pddl::Atom term{c.function->predicate, {}, {}};
            for (const auto &arg : c.function->args)
                term.args.push_back(resolve(arg, binding));
            auto value = problem_.function_values.find(term);
            if (value == problem_.function_values.end())
                return term.to_string();
            cost += value->second;
        }
        return "";
    }

public:
    std::vector<std::string> atoms() const { return {state_.begin(), state_.end()}; }

private:
    const pddl::Domain &domain_;
    const pddl::Problem &problem_;
    std::set<std::string> state_;
    std::map<std::string, std::vector<std::string>> object_types_;
    long long cost_ = 0;
};

} // namespace

Validation validate_plan(const pddl::Domain &domain, const pddl::Problem &problem,
                         const std::vector<std::string> &plan) {
    Simulator simulator(domain, problem);
    Validation result;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        std::string error = simulator.apply(plan[i]);
        if (!error.empty()) {
            result.failed_step = static_cast<int>(i);
            result.error = "step " + std::to_string(i + 1) + ": " + error;
            return result;
        }
    }
    result.executed_cost = simulator.cost();
    result.final_state = simulator.atoms();
    for (const auto &goal : problem.goal) {
        if (!simulator.holds(goal, {})) {
            result.error = "goal " + goal.to_string() + " does not hold at the end of the plan";
            return result;
        }
    }
    result.valid = true;
    result.cost = simulator.cost();
    return result;
}

std::vector<std::string> read_plan_file(const std::string &path) {
    std::istringstream in(pddl::read_input_file(path));
    std::vector<std::string> plan;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos || line[start] == ';')
            continue;
        auto end = line.find_last_not_of(" \t\r");
        std::string step = line.substr(start, end - start + 1);
        if (step.front() != '(' || step.back() != ')')
            throw pddl::ParseError({path, number, static_cast<int>(start) + 1},
                                   "expected an action '(name arg ...)'");
        plan.push_back(step);
    }
    return plan;
}

} // namespace envdesign::validate
