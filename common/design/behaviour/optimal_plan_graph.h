#pragma once
// The graph of every cost-optimal plan of a ground task (issue 14, COST_OPTIMAL).
//
// With c* the optimal cost, a state s lies on an optimal plan exactly when it is reachable
// with g*(s) + h*(s) = c*, and an operator a leads from such an s to s' along an optimal
// plan exactly when g*(s) + cost(a) + h*(s') = c*. The optimal plans are then the paths of
// this graph from the initial state to a goal state (a plan may pass through a goal state
// and go on with zero-cost operators). With zero-cost operators the graph can have cycles:
// then there are infinitely many optimal plans, and the graph still describes all of them.
//
// How it is built, exactly and without enumerating plans:
//   1. forward, uniform-cost search (Dijkstra on g) that drops every state with
//      g + h > c* for an admissible h: every state of an optimal plan survives, with its
//      exact g*, because its optimal prefix does too;
//   2. backward, Dijkstra over the edges kept, from the goal states: h' >= h*, equal on the
//      states of optimal plans (their optimal suffixes were kept);
//   3. a state is in the graph when g + h' = c*, an edge when g(s) + cost + h'(s') = c*.
// Everything else has g + h' > c* (g >= g*, h' >= h*, and g* + h* = c* only on optimal
// plans), so nothing is kept that should not be.
//
// Example:
//   auto h = heuristics::make_heuristic(HeuristicKind::LMCUT, task);
//   OptimalPlanGraph graph = optimal_plan_graph(task, c_star, *h, limits, stop);
//   for (int e = graph.edge_begin(node); e < graph.edge_end(node); ++e) graph.edges[e] ...

#include "ground/ground_task.h"
#include "heuristics/heuristic.h"
#include "search/state_codec.h"
#include "search/state_estimates.h"
#include "search/state_registry.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace envdesign::design {

struct OptimalPlanGraph {
    enum class Status { SOLVED, LIMIT };
    struct Edge {
        int target = 0;             // a node
        ground::OperatorId op = -1; // of the ground task
    };

    Status status = Status::LIMIT;
    long long cost = 0;              // c*
    int initial = 0;                 // the node of the initial state
    std::vector<int> offsets;        // edges of node n: edges[offsets[n] .. offsets[n + 1])
    std::vector<Edge> edges;         // by source node
    std::vector<bool> goal;          // per node: the goal holds (a plan may end here)
    std::size_t states_explored = 0; // states registered by the forward search

    int num_nodes() const { return static_cast<int>(goal.size()); }
    int edge_begin(int node) const { return offsets[node]; }
    int edge_end(int node) const { return offsets[node + 1]; }
};

struct GraphLimits {
    std::size_t memory_limit_bytes = 0; // of the graph search's own data; 0: none
    std::function<bool()> stop;         // checked between expansions; true: give up (LIMIT)
};

// The optimal-plan graph of `task`, whose optimal cost is `optimal_cost` (solved already,
// e.g. by the planner). `heuristic` (`estimates`, search/state_estimates.h: they may depend
// on the path a state was reached by) must be admissible for `task`. LIMIT when
// the memory limit or `stop` cut it short. Throws std::logic_error if no plan of cost
// `optimal_cost` exists (the cost given was not the task's optimum).
OptimalPlanGraph optimal_plan_graph(const ground::GroundTask &task, long long optimal_cost,
                                    heuristics::Heuristic &heuristic, const GraphLimits &limits);
OptimalPlanGraph optimal_plan_graph(const ground::GroundTask &task, long long optimal_cost,
                                    search::StateEstimates &estimates, const GraphLimits &limits);

} // namespace envdesign::design
