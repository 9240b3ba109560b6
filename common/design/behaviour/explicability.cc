#include "design/behaviour/explicability.h"

#include "design/model/compilation.h"
#include "design/model/lifted_key.h"
#include "ground/grounder.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <cmath>

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

// An optimal plan of P_mod argued from the human's optimal plan, without its search: every
// plan of P_mod is one of P_H and costs people at least c_H*, so the human's plan is most
// explicable where it is valid in P_mod, and the robot's cheapest among those where both
// models charge every action alike (costs_agree). The human's plan comes from its own
// search, so the answer (and the plan reported) does not depend on what was solved before.
std::optional<PlanOutcome> known_most_explicable(const ModelPair &models,
                                                 const CompiledTask &compiled,
                                                 const TaskExplicability &human) {
    if (!human.human_optimal_cost || std::isinf(*human.human_optimal_cost) || !human.human_plan ||
        !costs_agree(models))
        return std::nullopt;
    const auto optimum = static_cast<long long>(*human.human_optimal_cost);
    auto v = validate::validate_plan(compiled.domain, compiled.problem, *human.human_plan);
    if (!v.valid || v.cost != optimum)
        return std::nullopt;
    return PlanOutcome{PlanStatus::SOLVED, optimum, optimum, *human.human_plan};
}

} // namespace

PlanOutcome solve_model(const pddl::Domain &domain, const pddl::Problem &problem,
                        PlanCache &planner, const Deadline &deadline,
                        const PlanCache::KnownAnswer &known) {
    return planner.solve_model(
        lifted_key(domain, problem),
        [&] {
            return ground::ground(domain, problem, nullptr, [&] { return deadline.expired(); });
        },
        deadline, known);
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
    // P_H first: its optimal plan often answers P_mod too (known_most_explicable).
    TaskExplicability result;
    if (!solve_human(models, planner, deadline, result))
        return TaskExplicability{};
    CompiledTask compiled = compile_explicable(models);
    PlanOutcome explicable = solve_model(compiled.domain, compiled.problem, planner, deadline, [&] {
        return known_most_explicable(models, compiled, result);
    });
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
