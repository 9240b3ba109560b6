#pragma once
// Hand-built tasks for the search tests.

#include "ground/ground_task.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::search::testing {

inline ground::GroundTask make_task(int num_facts) {
    ground::GroundTask task;
    for (int f = 0; f < num_facts; ++f)
        task.fact_names.push_back("(f" + std::to_string(f) + ")");
    return task;
}

inline void add_op(ground::GroundTask &task, std::string name, std::vector<ground::FactId> pre,
                   std::vector<ground::FactId> add, std::vector<ground::FactId> del, int cost = 1,
                   int secondary = 0) {
    task.operators.push_back({std::move(name), pre, add, del, cost, secondary});
}

// A graph as a task: one fact "at v" per vertex (one mutex group), one operator per edge.
struct Edge {
    int from, to, cost, secondary = 0;
};

inline ground::GroundTask graph_task(int vertices, const std::vector<Edge> &edges, int start,
                                     int goal) {
    ground::GroundTask task = make_task(vertices);
    std::vector<ground::FactId> group;
    for (int v = 0; v < vertices; ++v)
        group.push_back(v);
    task.mutex_groups.push_back(group);
    for (const Edge &e : edges)
        add_op(task, "(move v" + std::to_string(e.from) + " v" + std::to_string(e.to) + ")",
               {e.from}, {e.to}, {e.from}, e.cost, e.secondary);
    task.initial_state = {start};
    task.goal = {goal};
    task.has_action_costs = true;
    return task;
}

// An n x n grid robot: facts "at x y" (one mutex group); moves of cost 1 in 4 directions.
inline ground::GroundTask grid_task(int n, std::vector<int> blocked = {}) {
    auto id = [n](int x, int y) { return y * n + x; };
    std::vector<Edge> edges;
    auto free = [&](int v) {
        return std::find(blocked.begin(), blocked.end(), v) == blocked.end();
    };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            if (!free(id(x, y)))
                continue;
            if (x + 1 < n && free(id(x + 1, y))) {
                edges.push_back({id(x, y), id(x + 1, y), 1});
                edges.push_back({id(x + 1, y), id(x, y), 1});
            }
            if (y + 1 < n && free(id(x, y + 1))) {
                edges.push_back({id(x, y), id(x, y + 1), 1});
                edges.push_back({id(x, y + 1), id(x, y), 1});
            }
        }
    ground::GroundTask task = graph_task(n * n, edges, id(0, 0), id(n - 1, n - 1));
    task.has_action_costs = false;
    return task;
}

// The plan's (primary, secondary) cost, or (-1, -1) if it is not applicable or misses the goal.
inline std::pair<long long, long long> replayed_costs(const ground::GroundTask &task,
                                                      const std::vector<ground::OperatorId> &plan) {
    std::set<ground::FactId> state(task.initial_state.begin(), task.initial_state.end());
    long long cost = 0, secondary = 0;
    for (ground::OperatorId op : plan) {
        const ground::GroundOperator &o = task.operators[op];
        for (ground::FactId p : o.pre)
            if (!state.count(p))
                return {-1, -1};
        for (ground::FactId d : o.del)
            state.erase(d);
        state.insert(o.add.begin(), o.add.end());
        cost += o.cost;
        secondary += o.secondary_cost;
    }
    for (ground::FactId g : task.goal)
        if (!state.count(g))
            return {-1, -1};
    return {cost, secondary};
}

} // namespace envdesign::search::testing
