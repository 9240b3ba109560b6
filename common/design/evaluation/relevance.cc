#include "design/evaluation/relevance.h"

#include "design/behaviour/explicability.h"
#include "design/model/configuration.h"

#include <map>
#include <set>
#include <sstream>

namespace envdesign::design {
namespace {

struct Touched {
    std::set<std::string> schemas;        // "move"
    std::set<std::string> ground_actions; // "(move c00 c01)"
    std::set<std::string> atoms;          // "(connected c00 c01)"
};

// "(move c00 c01)" -> {"move", "c00", "c01"}
std::vector<std::string> split_step(const std::string &step) {
    std::string inner = step.substr(1, step.size() - 2);
    std::istringstream in(inner);
    std::vector<std::string> words;
    for (std::string w; in >> w;)
        words.push_back(w);
    return words;
}

void add_plan(const pddl::Domain &domain, const std::vector<std::string> &plan, Touched &touched) {
    for (const auto &step : plan) {
        touched.ground_actions.insert(step);
        auto words = split_step(step);
        const pddl::Action *action = words.empty() ? nullptr : domain.find_action(words[0]);
        if (!action)
            continue;
        touched.schemas.insert(action->name);
        std::map<std::string, std::string> binding;
        for (std::size_t i = 0; i < action->parameters.size() && i + 1 < words.size(); ++i)
            binding[action->parameters[i].name] = words[i + 1];
        auto add_literals = [&](const std::vector<pddl::Literal> &literals) {
            for (const auto &l : literals) {
                pddl::Atom atom = l.atom;
                for (auto &arg : atom.args)
                    if (auto it = binding.find(arg); it != binding.end())
                        arg = it->second;
                touched.atoms.insert(atom.to_string());
            }
        };
        add_literals(action->precondition);
        add_literals(action->effect);
    }
}

// The planner's plan (PLANNERS): what is relevant depends on the actions the plan takes, and
// the pruning keeps the designs it chose with the planner's plans.
void add_optimal_plan(const pddl::Domain &domain, const pddl::Problem &problem, PlanCache &planner,
                      const Deadline &deadline, Touched &touched) {
    PlanOutcome outcome = solve_model(domain, problem, planner, deadline, PlanChoice::PLANNERS);
    if (outcome.status == PlanStatus::SOLVED)
        add_plan(domain, outcome.plan, touched);
}

bool touches(const Edit &edit, const Touched &touched) {
    switch (edit.kind) {
    case EditKind::ADD_GOAL:
    case EditKind::REMOVE_GOAL:
        return true;
    case EditKind::ADD_PREDICATE:
        return false;
    case EditKind::ADD_INIT:
    case EditKind::REMOVE_INIT:
        return touched.atoms.count(edit.expression.to_string()) > 0;
    case EditKind::REMOVE_ACTION:
        return edit.expression.is_list
                   ? touched.ground_actions.count(edit.expression.to_string()) > 0
                   : touched.schemas.count(edit.expression.symbol) > 0;
    default:
        return touched.schemas.count(edit.action) > 0;
    }
}

} // namespace

std::vector<int> relevant_modifications(const DesignProblem &problem,
                                        const Configuration &configuration, PlanCache &planner,
                                        const Deadline &deadline) {
    Touched touched;
    for (std::size_t t = 0; t < problem.tasks.size(); ++t) {
        ModelPair models = configured_models(problem, configuration, static_cast<int>(t));
        add_optimal_plan(models.robot_domain, models.robot_problem, planner, deadline, touched);
        add_optimal_plan(models.human_domain, models.human_problem, planner, deadline, touched);
    }
    std::vector<int> relevant;
    for (std::size_t m = 0; m < problem.modifications.size(); ++m) {
        const auto &edits = problem.modifications[m].edits;
        for (const auto &edit : edits) {
            if (touches(edit, touched)) {
                relevant.push_back(static_cast<int>(m));
                break;
            }
        }
    }
    return relevant;
}

} // namespace envdesign::design
