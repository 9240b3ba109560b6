#include "design/behaviour/optimal_plan_graph.h"

#include "search/state_registry.h"
#include "search/successor_generator.h"

#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace envdesign::design {
namespace {

using search::StateID;
constexpr long long UNREACHED = std::numeric_limits<long long>::max() / 4;
constexpr int CHECK_INTERVAL = 256;

struct RawEdge {
    StateID from;
    StateID to;
    ground::OperatorId op;
};

using Queue = std::priority_queue<std::pair<long long, StateID>,
                                  std::vector<std::pair<long long, StateID>>, std::greater<>>;

bool is_goal(const ground::GroundTask &task, const search::UnpackedState &state) {
    for (ground::FactId f : task.goal)
        if (!state.holds(f))
            return false;
    return true;
}

// A state registered but not yet estimated: its estimate waits for an edge that needs it.
constexpr int UNKNOWN = -1;

// Step 1 of the header: every state with g + h <= c*, expanded in g order. A plain struct:
// steps 2 and 3 read what it found.
struct ForwardSearch {
    ForwardSearch(const ground::GroundTask &task, long long bound,
                  search::StateEstimates &estimates, const GraphLimits &limits)
        : task_(task), bound_(bound), estimates_(estimates), limits_(limits), registry_(task),
          successors_(task), state_(registry_.codec()), successor_(registry_.codec()) {}

    // False when a limit stopped it.
    bool run() {
        StateID init = registry_.insert_facts(task_.initial_state).id;
        registry_.unpack(init, state_);
        grow(init);
        h_[init] = estimates_.initial(init, state_);
        if (h_[init] == heuristics::DEAD_END || h_[init] > bound_)
            return true;
        g_[init] = 0;
        open_.push({0, init});
        long long steps = 0;
        while (!open_.empty()) {
            auto [g, s] = open_.top();
            open_.pop();
            if (g > g_[s] || expanded_[s])
                continue;
            if (++steps % CHECK_INTERVAL == 0 && limited())
                return false;
            expand(s);
        }
        return true;
    }

    const ground::GroundTask &task_;
    long long bound_;
    search::StateEstimates &estimates_;
    const GraphLimits &limits_;
    search::StateRegistry registry_;
    search::SuccessorGenerator successors_;
    search::UnpackedState state_, successor_;
    std::vector<ground::OperatorId> applicable_;
    std::vector<long long> g_;
    std::vector<int> h_;
    std::vector<char> expanded_, goal_;
    std::vector<RawEdge> edges_;
    Queue open_;

    void grow(StateID id) {
        if (id >= g_.size()) {
            g_.resize(id + 1, UNREACHED);
            h_.resize(id + 1, UNKNOWN);
            expanded_.resize(id + 1, 0);
            goal_.resize(id + 1, 0);
        }
    }

    void expand(StateID s) {
        expanded_[s] = 1;
        registry_.unpack(s, state_);
        goal_[s] = is_goal(task_, state_) ? 1 : 0;
        successors_.applicable_operators(state_, applicable_);
        for (ground::OperatorId op : applicable_) {
            auto [t, is_new] = registry_.insert_successor(s, op);
            if (is_new)
                grow(t);
            long long g = g_[s] + task_.operators[op].cost;
            if (!within_bound(s, op, t, bound_ - g))
                continue;
            edges_.push_back({s, t, op});
            if (g < g_[t]) {
                g_[t] = g;
                open_.push({g, t});
            }
        }
        estimates_.expanded(s);
    }

    // Whether h*(t) may be <= budget, as far as the estimates tell; estimates t if needed.
    bool within_bound(StateID s, ground::OperatorId op, StateID t, long long budget) {
        if (budget < 0 || estimates_.inherited(s, op) > budget)
            return false;
        if (h_[t] == UNKNOWN) {
            registry_.unpack(t, successor_);
            h_[t] = estimates_.successor(t, successor_, s, op);
        }
        return h_[t] != heuristics::DEAD_END && h_[t] <= budget;
    }

    bool limited() const {
        if (limits_.stop && limits_.stop())
            return true;
        if (limits_.memory_limit_bytes == 0)
            return false;
        std::size_t bytes = registry_.memory_bytes() + edges_.capacity() * sizeof(RawEdge) +
                            g_.capacity() * (sizeof(long long) + sizeof(int) + 2) +
                            open_.size() * sizeof(std::pair<long long, StateID>) +
                            estimates_.memory_bytes();
        return bytes > limits_.memory_limit_bytes;
    }
};

// Step 2: h' by Dijkstra backwards over the kept edges, from the goal states expanded.
std::vector<long long> backward_distances(const ForwardSearch &f) {
    std::size_t n = f.g_.size();
    std::vector<int> offsets(n + 1, 0);
    for (const RawEdge &e : f.edges_)
        ++offsets[e.to + 1];
    for (std::size_t i = 0; i < n; ++i)
        offsets[i + 1] += offsets[i];
    std::vector<int> by_target(f.edges_.size());
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t i = 0; i < f.edges_.size(); ++i)
        by_target[fill[f.edges_[i].to]++] = static_cast<int>(i);
    std::vector<long long> h(n, UNREACHED);
    Queue open;
    for (StateID s = 0; s < n; ++s)
        if (f.expanded_[s] && f.goal_[s])
            h[s] = 0, open.push({0, s});
    while (!open.empty()) {
        auto [d, s] = open.top();
        open.pop();
        if (d > h[s])
            continue;
        for (int k = offsets[s]; k < offsets[s + 1]; ++k) {
            const RawEdge &e = f.edges_[by_target[k]];
            long long candidate = d + f.task_.operators[e.op].cost;
            if (candidate < h[e.from]) {
                h[e.from] = candidate;
                open.push({candidate, e.from});
            }
        }
    }
    return h;
}

} // namespace

OptimalPlanGraph optimal_plan_graph(const ground::GroundTask &task, long long optimal_cost,
                                    heuristics::Heuristic &heuristic, const GraphLimits &limits) {
    search::HeuristicEstimates estimates(heuristic);
    return optimal_plan_graph(task, optimal_cost, estimates, limits);
}

OptimalPlanGraph optimal_plan_graph(const ground::GroundTask &task, long long optimal_cost,
                                    search::StateEstimates &estimates, const GraphLimits &limits) {
    OptimalPlanGraph graph;
    graph.cost = optimal_cost;
    ForwardSearch forward(task, optimal_cost, estimates, limits);
    bool finished = forward.run();
    graph.states_explored = forward.registry_.size();
    if (!finished)
        return graph; // LIMIT
    std::vector<long long> h = backward_distances(forward);
    // Step 3: the nodes and edges on optimal plans.
    std::size_t n = forward.g_.size();
    std::vector<int> node_of(n, -1);
    int nodes = 0;
    for (StateID s = 0; s < n; ++s)
        if (forward.expanded_[s] && h[s] < UNREACHED && forward.g_[s] + h[s] == optimal_cost)
            node_of[s] = nodes++;
    if (n == 0 || node_of[0] < 0)
        throw std::logic_error("no plan of the given optimal cost " + std::to_string(optimal_cost));
    graph.initial = node_of[0]; // the initial state was registered first
    graph.goal.assign(nodes, false);
    graph.offsets.assign(nodes + 1, 0);
    std::vector<std::pair<int, OptimalPlanGraph::Edge>> kept;
    for (const RawEdge &e : forward.edges_) {
        if (node_of[e.from] < 0 || h[e.to] >= UNREACHED)
            continue;
        if (forward.g_[e.from] + task.operators[e.op].cost + h[e.to] == optimal_cost)
            kept.push_back({node_of[e.from], {node_of[e.to], e.op}});
    }
    for (StateID s = 0; s < n; ++s)
        if (node_of[s] >= 0 && forward.goal_[s])
            graph.goal[node_of[s]] = true;
    for (const auto &[from, edge] : kept)
        ++graph.offsets[from + 1];
    for (int i = 0; i < nodes; ++i)
        graph.offsets[i + 1] += graph.offsets[i];
    graph.edges.resize(kept.size());
    std::vector<int> fill(graph.offsets.begin(), graph.offsets.end() - 1);
    for (const auto &[from, edge] : kept)
        graph.edges[fill[from]++] = edge;
    graph.status = OptimalPlanGraph::Status::SOLVED;
    return graph;
}

} // namespace envdesign::design
