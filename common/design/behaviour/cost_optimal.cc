#include "design/behaviour/cost_optimal.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/explicability.h"
#include "design/behaviour/optimal_plan_graph.h"
#include "design/behaviour/worst_case.h"
#include "ground/grounder.h"
#include "ground/simplify.h"
#include "heuristics/make_heuristic.h"
#include "search/inherited_lmcut.h"

#include <algorithm>
#include <chrono>
#include <set>

namespace envdesign::design {
namespace {

TaskExplicability inexplicable(std::optional<double> human_optimal_cost) {
    TaskExplicability out;
    out.status = ExplicabilityStatus::INEXPLICABLE;
    out.human_optimal_cost = human_optimal_cost;
    return out;
}

// The planner's time limit (per search) and the deadline, whichever comes first.
GraphLimits limits_of(const planning::PlannerOptions &options, const Deadline &deadline) {
    GraphLimits limits;
    limits.memory_limit_bytes = options.limits.memory_limit_bytes;
    double seconds = options.limits.time_limit_s;
    auto start = std::chrono::steady_clock::now();
    limits.stop = [seconds, start, deadline] {
        if (deadline.expired())
            return true;
        return seconds > 0 &&
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >=
                   seconds;
    };
    return limits;
}

// Any admissible estimates give the same graph; with LM-cut, those inherited along the path
// cost a fraction of LM-cut from scratch in every state (search/inherited_lmcut.h).
OptimalPlanGraph plan_graph(const ground::GroundTask &task, long long optimal_cost,
                            const planning::PlannerOptions &options, const GraphLimits &limits) {
    if (options.heuristic == heuristics::HeuristicKind::LMCUT) {
        search::InheritedLmCut estimates(task);
        return optimal_plan_graph(task, optimal_cost, estimates, limits);
    }
    auto heuristic = heuristics::make_heuristic(options.heuristic, task);
    return optimal_plan_graph(task, optimal_cost, *heuristic, limits);
}

std::vector<std::string> graph_actions(const OptimalPlanGraph &graph,
                                       const ground::GroundTask &task) {
    std::set<std::string> names;
    for (const auto &edge : graph.edges)
        names.insert(task.operators[edge.op].name);
    return {names.begin(), names.end()};
}

} // namespace

TaskExplicability evaluate_cost_optimal(const ModelPair &models, const ObjectiveWeights &weights,
                                        PlanCache &planner, const Deadline &deadline) {
    PlanOutcome robot = solve_model(models.robot_domain, models.robot_problem, planner, deadline);
    if (robot.status == PlanStatus::LIMIT)
        return {};
    if (robot.status == PlanStatus::UNSOLVABLE)
        return inexplicable(std::nullopt);
    PlanOutcome human = solve_model(models.human_domain, models.human_problem, planner, deadline);
    if (human.status == PlanStatus::LIMIT)
        return {};
    if (human.status == PlanStatus::UNSOLVABLE)
        return inexplicable(INF);

    GraphLimits limits = limits_of(planner.options(), deadline);
    // Without relevance pruning: a zero-cost action that changes nothing the goal needs is
    // still part of optimal plans, and the human model must see every action of a plan.
    ground::GroundTask robot_task;
    ground::GroundTask human_task;
    try {
        robot_task =
            ground::ground(models.robot_domain, models.robot_problem, nullptr, limits.stop, false);
        human_task =
            ground::ground(models.human_domain, models.human_problem, nullptr, limits.stop, false);
    } catch (const ground::GroundingStopped &) {
        return {};
    }
    // Facts nothing reads only tell states apart that every plan treats alike (Blocksworld's
    // from-table of a block no modification restricts doubled the graph's states).
    ground::remove_unread(robot_task);
    ground::remove_unread(human_task);
    OptimalPlanGraph graph = plan_graph(robot_task, robot.cost, planner.options(), limits);
    if (graph.status == OptimalPlanGraph::Status::LIMIT)
        return {};
    Case which = behaviour_of(weights.behaviour).best_case ? Case::BEST : Case::WORST;
    HumanCost seen = human_cost_of_optimal_plans(graph, robot_task, human_task, which, limits);
    if (seen.status == HumanCost::Status::LIMIT)
        return {};

    TaskExplicability out;
    out.status = ExplicabilityStatus::SOLVED;
    out.robot_cost = static_cast<double>(robot.cost);
    out.human_optimal_cost = static_cast<double>(human.cost);
    out.human_plan = std::move(human.plan);
    out.human_plan_cost = seen.cost;
    out.ie = inexplicability(seen.cost, *out.human_optimal_cost, weights.distance);
    out.plan =
        seen.plan.empty() && which == Case::BEST ? std::move(robot.plan) : std::move(seen.plan);
    out.optimal_actions = graph_actions(graph, robot_task);
    return out;
}

} // namespace envdesign::design
