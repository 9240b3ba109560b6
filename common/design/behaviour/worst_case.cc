#include "design/behaviour/worst_case.h"

#include "search/state_registry.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <span>
#include <unordered_map>

namespace envdesign::design {
namespace {

using search::StateID;
constexpr int DEADLINE_CHECK_STEPS = 256;
constexpr long long UNSET = std::numeric_limits<long long>::min() / 4;

// The product of the optimal-plan graph with the human model's states. Only valid human
// states are nodes: a step into "not valid for the human" is reported by the caller.
class Product {
public:
    struct Node {
        int robot = 0;
        StateID human = 0;
        int parent = -1;            // the node it was reached from (BFS tree or best path)
        ground::OperatorId op = -1; // the robot operator from the parent
    };
    struct Edge {
        int target = 0;
        long long cost = 0; // human cost
        ground::OperatorId op = -1;
    };

    Product(const OptimalPlanGraph &graph, const ground::GroundTask &robot,
            const ground::GroundTask &human, const GraphLimits &limits)
        : graph_(graph), robot_(robot), human_(human), limits_(limits), registry_(human),
          state_(registry_.codec()) {
        std::unordered_map<std::string, ground::OperatorId> by_name;
        for (ground::OperatorId o = 0; o < human.num_operators(); ++o)
            by_name.emplace(human.operators[o].name, o);
        human_op_.assign(robot.num_operators(), -1);
        for (ground::OperatorId o = 0; o < robot.num_operators(); ++o) {
            auto it = by_name.find(robot.operators[o].name);
            if (it != by_name.end())
                human_op_[o] = it->second;
        }
        start_ = find_or_add(graph.initial, registry_.insert_facts(human.initial_state).id).first;
    }

    int start() const { return start_; }
    int size() const { return static_cast<int>(nodes_.size()); }
    const Node &node(int i) const { return nodes_[i]; }
    Node &node(int i) { return nodes_[i]; }

    std::pair<int, bool> find_or_add(int robot, StateID human) {
        std::uint64_t key = (std::uint64_t(robot) << 32) | human;
        auto [it, is_new] = index_.try_emplace(key, static_cast<int>(nodes_.size()));
        if (is_new)
            nodes_.push_back({robot, human, -1, -1});
        return {it->second, is_new};
    }

    // Loads node i's human state for the tests below.
    void load(int i) { registry_.unpack(nodes_[i].human, state_); }
    bool robot_goal(int i) const { return graph_.goal[nodes_[i].robot]; }
    bool human_goal() const {
        return std::all_of(human_.goal.begin(), human_.goal.end(),
                           [&](ground::FactId f) { return state_.holds(f); });
    }
    // The human operator of robot operator `op` if it applies in the loaded state; else -1.
    ground::OperatorId human_step(ground::OperatorId op) const {
        ground::OperatorId h = human_op_[op];
        if (h < 0)
            return -1;
        for (ground::FactId f : human_.operators[h].pre)
            if (!state_.holds(f))
                return -1;
        return h;
    }
    // The node after robot edge `edge` from node i, whose human step is `h`.
    std::pair<int, bool> successor(int i, const OptimalPlanGraph::Edge &edge,
                                   ground::OperatorId h) {
        StateID next = registry_.insert_successor(nodes_[i].human, h).id;
        return find_or_add(edge.target, next);
    }
    long long human_cost(ground::OperatorId h) const { return human_.operators[h].cost; }

    // The robot operators from the start to node i along the parents.
    std::vector<std::string> plan_to(int i) const {
        std::vector<std::string> plan;
        for (; nodes_[i].parent >= 0; i = nodes_[i].parent)
            plan.push_back(robot_.operators[nodes_[i].op].name);
        std::reverse(plan.begin(), plan.end());
        return plan;
    }
    // A shortest (in steps) continuation in the robot graph from robot node `from` to a goal.
    std::vector<std::string> robot_path_to_goal(int from) const {
        std::vector<int> parent(graph_.num_nodes(), -2), via(graph_.num_nodes(), -1);
        std::deque<int> queue{from};
        parent[from] = -1;
        while (!queue.empty()) {
            int n = queue.front();
            queue.pop_front();
            if (graph_.goal[n]) {
                std::vector<std::string> path;
                for (; parent[n] >= 0; n = parent[n])
                    path.push_back(robot_.operators[via[n]].name);
                std::reverse(path.begin(), path.end());
                return path;
            }
            for (int e = graph_.edge_begin(n); e < graph_.edge_end(n); ++e) {
                int t = graph_.edges[e].target;
                if (parent[t] == -2)
                    parent[t] = n, via[t] = graph_.edges[e].op, queue.push_back(t);
            }
        }
        return {}; // not reached: every node of the graph lies on an optimal plan
    }
    std::span<const OptimalPlanGraph::Edge> graph_edges(int robot) const {
        return {graph_.edges.data() + graph_.edge_begin(robot),
                graph_.edges.data() + graph_.edge_end(robot)};
    }
    const std::string &robot_name(ground::OperatorId op) const { return robot_.operators[op].name; }

    bool limited(long long steps) const {
        if (steps % DEADLINE_CHECK_STEPS != 0)
            return false;
        if (limits_.stop && limits_.stop())
            return true;
        std::size_t bytes = registry_.memory_bytes() + nodes_.capacity() * sizeof(Node) +
                            index_.size() * 48 + edges_bytes;
        return limits_.memory_limit_bytes > 0 && bytes > limits_.memory_limit_bytes;
    }
    std::size_t edges_bytes = 0; // the caller's adjacency, for the memory limit

private:
    const OptimalPlanGraph &graph_;
    const ground::GroundTask &robot_;
    const ground::GroundTask &human_;
    const GraphLimits &limits_;
    search::StateRegistry registry_;
    search::UnpackedState state_;
    std::vector<ground::OperatorId> human_op_;
    std::vector<Node> nodes_;
    std::unordered_map<std::uint64_t, int> index_;
    int start_ = 0;
};

using Adjacency = std::vector<std::vector<Product::Edge>>;

HumanCost infinite(std::vector<std::string> plan, const Product &p) {
    HumanCost out;
    out.status = HumanCost::Status::SOLVED;
    out.cost = std::numeric_limits<double>::infinity();
    out.plan = std::move(plan);
    out.product_nodes = static_cast<std::size_t>(p.size());
    return out;
}

// Strongly connected components (Tarjan, iterative); numbered in completion order, so an
// edge between two components always goes to a lower number.
std::vector<int> components(const Adjacency &adjacency, int &count) {
    int n = static_cast<int>(adjacency.size());
    std::vector<int> index(n, -1), low(n, 0), component(n, -1), stack;
    std::vector<std::pair<int, std::size_t>> calls; // node, next edge
    int next_index = 0;
    count = 0;
    for (int root = 0; root < n; ++root) {
        if (index[root] >= 0)
            continue;
        calls.push_back({root, 0});
        index[root] = low[root] = next_index++;
        stack.push_back(root);
        while (!calls.empty()) {
            auto &[v, k] = calls.back();
            if (k < adjacency[v].size()) {
                int w = adjacency[v][k++].target;
                if (index[w] < 0) {
                    index[w] = low[w] = next_index++;
                    stack.push_back(w);
                    calls.push_back({w, 0});
                } else if (component[w] < 0) {
                    low[v] = std::min(low[v], index[w]);
                }
                continue;
            }
            int done = v;
            calls.pop_back();
            if (!calls.empty())
                low[calls.back().first] = std::min(low[calls.back().first], low[done]);
            if (low[done] == index[done]) {
                int w;
                do {
                    w = stack.back();
                    stack.pop_back();
                    component[w] = count;
                } while (w != done);
                ++count;
            }
        }
    }
    return component;
}

// Robot operators of a shortest (in steps) path from `from` to a node satisfying `reached`,
// over edges accepted by `use`; `to` gets the node reached.
std::vector<std::string> walk(const Adjacency &adjacency, const Product &p, int from,
                              const std::function<bool(int)> &reached,
                              const std::function<bool(int)> &use, int &to) {
    std::vector<int> parent(adjacency.size(), -2);
    std::vector<ground::OperatorId> via(adjacency.size(), -1);
    std::deque<int> queue{from};
    parent[from] = -1;
    while (!queue.empty()) {
        int v = queue.front();
        queue.pop_front();
        if (reached(v)) {
            to = v;
            std::vector<std::string> path;
            for (; parent[v] >= 0; v = parent[v])
                path.push_back(p.robot_name(via[v]));
            std::reverse(path.begin(), path.end());
            return path;
        }
        for (const auto &e : adjacency[v])
            if (parent[e.target] == -2 && use(e.target))
                parent[e.target] = v, via[e.target] = e.op, queue.push_back(e.target);
    }
    to = -1;
    return {};
}

void append(std::vector<std::string> &plan, const std::vector<std::string> &more) {
    plan.insert(plan.end(), more.begin(), more.end());
}

// Builds the whole product breadth first into `adjacency`; stops early (returning the
// answer) at a limit or at the first plan people cannot follow.
std::optional<HumanCost> explore(Product &p, Adjacency &adjacency) {
    long long steps = 0;
    for (int i = 0; i < p.size(); ++i) { // nodes are appended as found
        if (p.limited(++steps))
            return HumanCost{};
        adjacency.emplace_back();
        p.load(i);
        if (p.robot_goal(i) && !p.human_goal())
            return infinite(p.plan_to(i), p); // ends where the human goal does not hold
        for (const auto &edge : p.graph_edges(p.node(i).robot)) {
            ground::OperatorId h = p.human_step(edge.op);
            if (h < 0) { // the human model cannot follow this step
                std::vector<std::string> plan = p.plan_to(i);
                plan.push_back(p.robot_name(edge.op));
                append(plan, p.robot_path_to_goal(edge.target));
                return infinite(std::move(plan), p);
            }
            auto [t, is_new] = p.successor(i, edge, h);
            if (is_new)
                p.node(t).parent = i, p.node(t).op = edge.op;
            adjacency[i].push_back({t, p.human_cost(h), edge.op});
            p.edges_bytes += sizeof(Product::Edge);
        }
    }
    return std::nullopt;
}

// A cycle that costs the human something: plans round it k times cost ever more. The plan
// reported goes round it once.
std::optional<HumanCost> costly_cycle(const Product &p, const Adjacency &adjacency,
                                      const std::vector<int> &component) {
    for (int u = 0; u < p.size(); ++u)
        for (const auto &e : adjacency[u]) {
            if (e.cost == 0 || component[e.target] != component[u])
                continue;
            int c = component[u], at = -1;
            auto inside = [&](int v) { return component[v] == c; };
            std::vector<std::string> plan = p.plan_to(u);
            plan.push_back(p.robot_name(e.op));
            append(plan, walk(
                             adjacency, p, e.target, [&](int v) { return v == u; }, inside, at));
            append(plan, walk(
                             adjacency, p, u, [&](int v) { return p.robot_goal(v); },
                             [](int) { return true; }, at));
            return infinite(std::move(plan), p);
        }
    return std::nullopt;
}

// The longest human cost to an end, component by component (sinks first); within a
// component every edge costs 0, so all its nodes share one value.
HumanCost longest(const Product &p, const Adjacency &adjacency, const std::vector<int> &component,
                  int count) {
    std::vector<long long> value(count, UNSET);
    std::vector<std::pair<int, int>> choice(count, {-1, -1}); // node, edge index (-1: end)
    std::vector<std::vector<int>> members(count);
    for (int v = 0; v < p.size(); ++v)
        members[component[v]].push_back(v);
    for (int c = 0; c < count; ++c)
        for (int v : members[c]) {
            if (p.robot_goal(v) && value[c] < 0)
                value[c] = 0, choice[c] = {v, -1};
            for (int k = 0; k < static_cast<int>(adjacency[v].size()); ++k) {
                const auto &e = adjacency[v][k];
                int d = component[e.target];
                if (d != c && value[d] != UNSET && e.cost + value[d] > value[c])
                    value[c] = e.cost + value[d], choice[c] = {v, k};
            }
        }
    HumanCost out;
    out.status = HumanCost::Status::SOLVED;
    out.cost = static_cast<double>(value[component[p.start()]]);
    out.product_nodes = static_cast<std::size_t>(p.size());
    for (int v = p.start();;) {
        int c = component[v], at = -1;
        int u = choice[c].first, k = choice[c].second; // a lambda captures u: no binding
        append(out.plan, walk(
                             adjacency, p, v, [&](int w) { return w == u; },
                             [&](int w) { return component[w] == c; }, at));
        if (k < 0)
            break;
        out.plan.push_back(p.robot_name(adjacency[u][k].op));
        v = adjacency[u][k].target;
    }
    return out;
}

HumanCost worst_case(Product &p) {
    Adjacency adjacency;
    if (auto early = explore(p, adjacency))
        return *early;
    int count = 0;
    std::vector<int> component = components(adjacency, count);
    if (auto unbounded = costly_cycle(p, adjacency, component))
        return *unbounded;
    return longest(p, adjacency, component, count);
}

// Dijkstra on human cost over the product, generated as it goes.
HumanCost best_case(Product &p) {
    std::vector<long long> distance{0};
    std::priority_queue<std::pair<long long, int>, std::vector<std::pair<long long, int>>,
                        std::greater<>>
        open;
    open.push({0, p.start()});
    long long steps = 0;
    while (!open.empty()) {
        auto [d, i] = open.top();
        open.pop();
        if (d > distance[i])
            continue;
        if (p.limited(++steps))
            return {};
        p.load(i);
        if (p.robot_goal(i) && p.human_goal()) {
            HumanCost out;
            out.status = HumanCost::Status::SOLVED;
            out.cost = static_cast<double>(d);
            out.plan = p.plan_to(i);
            out.product_nodes = static_cast<std::size_t>(p.size());
            return out;
        }
        for (const auto &edge : p.graph_edges(p.node(i).robot)) {
            ground::OperatorId h = p.human_step(edge.op);
            if (h < 0)
                continue; // not valid for the human from here on
            auto [t, is_new] = p.successor(i, edge, h);
            if (is_new)
                distance.push_back(std::numeric_limits<long long>::max());
            long long candidate = d + p.human_cost(h);
            if (candidate < distance[t]) {
                distance[t] = candidate;
                p.node(t).parent = i, p.node(t).op = edge.op;
                open.push({candidate, t});
            }
        }
    }
    return infinite({}, p); // no optimal robot plan is valid for the human
}

} // namespace

HumanCost human_cost_of_optimal_plans(const OptimalPlanGraph &graph,
                                      const ground::GroundTask &robot,
                                      const ground::GroundTask &human, Case which,
                                      const GraphLimits &limits) {
    Product product(graph, robot, human, limits);
    return which == Case::WORST ? worst_case(product) : best_case(product);
}

} // namespace envdesign::design
