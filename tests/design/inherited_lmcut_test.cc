// Inherited LM-cut (search/inherited_lmcut.h, issue 24): the residual LM-cut, the
// estimates' admissibility against the true cost to the goal, and the optimal-plan graph
// they prune being the one the blind search finds, on paper Blocksworld tasks.

#include "design/behaviour/optimal_plan_graph.h"
#include "ground/grounder.h"
#include "ground/simplify.h"
#include "heuristics/make_heuristic.h"
#include "pddl/parser.h"
#include "planning/planner.h"
#include "search/inherited_lmcut.h"
#include "search/state_registry.h"
#include "search/successor_generator.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace envdesign::design {
namespace {

const std::string BLOCKS = std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/";

// A paper Blocksworld task as the COST_OPTIMAL evaluation grounds it (cost_optimal.cc).
ground::GroundTask blocks_task(const std::string &problem) {
    pddl::Domain domain = pddl::parse_domain_file(BLOCKS + "domain-robot.pddl");
    pddl::Problem p = pddl::parse_problem_file(BLOCKS + problem, domain);
    ground::GroundTask task = ground::ground(domain, p, nullptr, {}, false);
    ground::remove_unread(task);
    return task;
}

long long optimal_cost_from(const ground::GroundTask &task, std::vector<ground::FactId> facts) {
    ground::GroundTask from = task;
    from.initial_state = std::move(facts);
    planning::PlanReport report = planning::plan_task(from, planning::PlannerOptions{});
    return report.status == search::SearchStatus::SOLVED ? report.cost : -1;
}

// The graph with nodes numbered in breadth-first order from the initial node, edges by
// operator name: equal for two searches exactly when they found the same graph.
using Shape = std::vector<std::tuple<int, std::string, int, bool>>;
Shape shape(const OptimalPlanGraph &graph, const ground::GroundTask &task) {
    std::map<int, int> order{{graph.initial, 0}};
    std::vector<int> queue{graph.initial};
    Shape out;
    for (std::size_t i = 0; i < queue.size(); ++i) {
        int n = queue[i];
        for (int e = graph.edge_begin(n); e < graph.edge_end(n); ++e) {
            int t = graph.edges[e].target;
            if (order.emplace(t, static_cast<int>(order.size())).second)
                queue.push_back(t);
            out.emplace_back(order[n], task.operators[graph.edges[e].op].name, order[t],
                             graph.goal[t]);
        }
    }
    return out;
}

// With nothing spent the residual is LM-cut itself; with LM-cut's own cuts spent, nothing
// is left (h^max is 0 on the costs LM-cut ends with).
TEST(InheritedLmCut, ResidualOfNothingSpentIsLmCutAndOfItsCutsIsZero) {
    ground::GroundTask task = blocks_task("10/init-5-1-goal-5-0.pddl");
    heuristics::LmCutLandmarks lmcut(task);
    std::vector<int> spent(task.num_operators(), 0);
    int h =
        lmcut.compute(task.initial_state, [&](std::span<const ground::OperatorId> cut, int cost) {
            for (ground::OperatorId op : cut)
                spent[op] += cost;
        });
    EXPECT_GT(h, 0);
    EXPECT_LE(h, optimal_cost_from(task, task.initial_state));
    std::vector<int> none(task.num_operators(), 0);
    EXPECT_EQ(lmcut.compute_residual(task.initial_state, none), h);
    EXPECT_EQ(lmcut.compute_residual(task.initial_state, spent), 0);
    EXPECT_EQ(lmcut.compute(task.initial_state), h); // nothing of the residual call stays
}

// Every successor of the initial state: its estimate is at least what it inherits and at
// most its true cost to the goal (A* from it).
TEST(InheritedLmCut, SuccessorEstimatesAreAdmissible) {
    ground::GroundTask task = blocks_task("10/init-5-1-goal-5-1.pddl");
    search::StateRegistry registry(task);
    search::SuccessorGenerator successors(task);
    search::UnpackedState state(registry.codec()), next(registry.codec());
    search::InheritedLmCut estimates(task);
    search::StateID init = registry.insert_facts(task.initial_state).id;
    registry.unpack(init, state);
    int h0 = estimates.initial(init, state);
    EXPECT_EQ(h0, heuristics::make_heuristic(heuristics::HeuristicKind::LMCUT, task)
                      ->compute(heuristics::StateView(state.facts, state.bits)));
    EXPECT_LE(h0, optimal_cost_from(task, state.facts));
    std::vector<ground::OperatorId> applicable;
    successors.applicable_operators(state, applicable);
    ASSERT_FALSE(applicable.empty());
    int lowered = 0;
    for (ground::OperatorId op : applicable) {
        search::StateID t = registry.insert_successor(init, op).id;
        registry.unpack(t, next);
        int inherited = estimates.inherited(init, op);
        int h = estimates.successor(t, next, init, op);
        long long star = optimal_cost_from(task, next.facts);
        EXPECT_LE(inherited, h) << task.operators[op].name;
        EXPECT_LE(h, star) << task.operators[op].name;
        EXPECT_GE(inherited, h0 - task.operators[op].cost) << task.operators[op].name;
        lowered += inherited < h0 ? 1 : 0;
    }
    EXPECT_GT(lowered, 0); // some first step is in a cut: its successors inherit less
}

// The same graph as the blind search's (the same nodes, edges and goals, up to numbering),
// from a fraction of the states.
TEST(InheritedLmCut, GraphEqualsTheBlindSearchsFromFewerStates) {
    for (const char *problem :
         {"10/init-5-1-goal-5-0.pddl", "10/init-5-1-goal-5-2.pddl", "05/init-4-1-goal-4-1.pddl"}) {
        ground::GroundTask task = blocks_task(problem);
        long long cost = optimal_cost_from(task, task.initial_state);
        ASSERT_GT(cost, 0) << problem;
        auto blind = heuristics::make_heuristic(heuristics::HeuristicKind::BLIND, task);
        OptimalPlanGraph reference = optimal_plan_graph(task, cost, *blind, {});
        search::InheritedLmCut estimates(task);
        OptimalPlanGraph graph = optimal_plan_graph(task, cost, estimates, {});
        ASSERT_EQ(graph.status, OptimalPlanGraph::Status::SOLVED) << problem;
        EXPECT_GT(graph.num_nodes(), cost) << problem; // several optimal plans
        EXPECT_EQ(shape(graph, task), shape(reference, task)) << problem;
        EXPECT_LT(graph.states_explored * 2, reference.states_explored) << problem;
    }
}

} // namespace
} // namespace envdesign::design
