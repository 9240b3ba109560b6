#include "design/behaviour/explicability.h"

#include "design/model/compilation.h"
#include "design/model/lifted_key.h"
#include "ground/grounder.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace envdesign::design {
namespace {

double as_cost(long long cost) { return static_cast<double>(cost); }

// Sets c_H* and the human's optimal plan; false if the deadline passed first.
bool solve_human(const ModelPair &models, PlanCache &planner, const Deadline &deadline,
                 TaskExplicability &result) {
    PlanOutcome human = solve_model(models.human_domain, models.human_problem, planner, deadline);
    if (human.status == PlanStatus::SOLVED) {
        result.human_optimal_cost = as_cost(human.cost);
        result.human_plan = std::move(human.plan);
    } else if (human.status == PlanStatus::UNSOLVABLE) {
        result.human_optimal_cost = INF;
    }
    return human.status != PlanStatus::LIMIT;
}

// Whether every object and constant of P_mod is one of P_H: otherwise a plan of P_mod may
// use an object people do not know of, and need not be a plan of P_H.
bool objects_known_to_people(const ModelPair &models) {
    std::set<std::string> human;
    for (const auto &o : models.human_problem.objects)
        human.insert(o.name);
    for (const auto &c : models.human_domain.constants)
        human.insert(c.name);
    auto known = [&](const std::vector<pddl::TypedName> &names) {
        return std::all_of(names.begin(), names.end(),
                           [&](const pddl::TypedName &n) { return human.count(n.name) > 0; });
    };
    return known(models.robot_problem.objects) && known(models.robot_domain.constants);
}

// An optimal plan of P_mod argued from the human's optimal plan, without its search. Where
// P_mod's objects are all people's, every plan of P_mod is one of P_H and costs people at
// least c_H*, so the human's plan is most explicable where it is valid in P_mod; it is the
// robot's cheapest among those where both models charge every action alike (costs_agree).
// Not memoized under P_mod's key: pairs whose P_H differ may share P_mod, and each must get
// the same plan whatever was evaluated before.
std::optional<PlanOutcome> known_most_explicable(const ModelPair &models,
                                                 const CompiledTask &compiled,
                                                 const TaskExplicability &human) {
    if (!human.human_optimal_cost || std::isinf(*human.human_optimal_cost) || !human.human_plan ||
        !costs_agree(models) || !objects_known_to_people(models))
        return std::nullopt;
    const auto optimum = static_cast<long long>(*human.human_optimal_cost);
    auto v = validate::validate_plan(compiled.domain, compiled.problem, *human.human_plan);
    if (!v.valid || v.cost != optimum)
        return std::nullopt;
    return PlanOutcome{PlanStatus::SOLVED, optimum, optimum, *human.human_plan};
}

} // namespace

PlanOutcome solve_model(const pddl::Domain &domain, const pddl::Problem &problem,
                        PlanCache &planner, const Deadline &deadline, PlanChoice choice) {
    return planner.solve_model(
        lifted_key(domain, problem),
        [&] {
            return ground::ground(domain, problem, nullptr, [&] { return deadline.expired(); });
        },
        deadline, choice);
}

double least_ie(Distance distance) { return distance == Distance::COST_DIFF ? 0.0 : 1.0; }

double inexplicability(double human_plan_cost, double human_optimal_cost, Distance distance) {
    if (std::isinf(human_plan_cost) || std::isinf(human_optimal_cost))
        return INF;
    double difference = std::abs(human_plan_cost - human_optimal_cost);
    return distance == Distance::COST_DIFF ? difference : std::exp(difference);
}

double ie_floor(double robot_optimal_cost, double human_optimal_cost, Distance distance) {
    if (!std::isfinite(robot_optimal_cost) || !std::isfinite(human_optimal_cost) ||
        robot_optimal_cost <= human_optimal_cost)
        return least_ie(distance);
    return inexplicability(robot_optimal_cost, human_optimal_cost, distance);
}

bool ie_floors_hold(const DesignProblem &problem) {
    return std::all_of(problem.tasks.begin(), problem.tasks.end(), [&](const DesignTask &t) {
        return human_costs_dominate(problem.robot_domain, t.robot_problem, problem.human_domain,
                                    t.human_problem);
    });
}

TaskExplicability evaluate_explicability(const ModelPair &models, Distance distance,
                                         PlanCache &planner, const Deadline &deadline,
                                         bool solve_human_anyway) {
    // P_H first: its optimal plan often answers P_mod too (known_most_explicable). Out of
    // time there, P_mod is still solved: an inexplicable task needs no c_H*.
    TaskExplicability result;
    const bool human_solved = solve_human(models, planner, deadline, result);
    CompiledTask compiled = compile_explicable(models);
    std::optional<PlanOutcome> known;
    if (human_solved)
        known = known_most_explicable(models, compiled, result);
    PlanOutcome explicable =
        known ? *known : solve_model(compiled.domain, compiled.problem, planner, deadline);
    if (explicable.status == PlanStatus::LIMIT)
        return TaskExplicability{};
    if (explicable.status == PlanStatus::UNSOLVABLE) {
        TaskExplicability inexplicable;
        inexplicable.status = ExplicabilityStatus::INEXPLICABLE;
        if (solve_human_anyway) {
            inexplicable.human_optimal_cost = result.human_optimal_cost;
            inexplicable.human_plan = std::move(result.human_plan);
        }
        return inexplicable;
    }
    if (!human_solved)
        return TaskExplicability{};
    result.human_plan_cost = as_cost(explicable.cost);
    result.robot_cost = as_cost(explicable.secondary_cost);
    result.plan = std::move(explicable.plan);
    result.ie = inexplicability(result.human_plan_cost, *result.human_optimal_cost, distance);
    // P_H has no plan although P_mod has one only if the models contradict the compilation.
    // (exp of a large cost gap overflows to inf; that is a huge IE, not a missing plan.)
    bool planless = std::isinf(result.human_plan_cost) || std::isinf(*result.human_optimal_cost);
    result.status = planless ? ExplicabilityStatus::INEXPLICABLE : ExplicabilityStatus::SOLVED;
    return result;
}

} // namespace envdesign::design
