#include "heuristics/fd_order.h"

#include <algorithm>
#include <deque>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <tuple>

namespace envdesign::heuristics {
namespace {

using Graph = std::vector<std::map<int, int>>; // source -> (target -> weight)
constexpr int GOAL_EDGE_BONUS = 100000;

// FD sorts atoms by (predicate, arguments): "(at a b)" -> {"at", "a", "b"}.
std::vector<std::string> atom_key(const std::string &name) {
    std::vector<std::string> key;
    std::string token;
    for (char c : name) {
        if (c == '(' || c == ')' || c == ' ') {
            if (!token.empty())
                key.push_back(std::move(token));
            token.clear();
        } else {
            token += c;
        }
    }
    if (!token.empty())
        key.push_back(token);
    return key;
}

// Variables as FD's fact_groups.sort_groups orders them: each group's facts by atom, the
// groups lexicographically by those atoms.
std::vector<std::vector<ground::FactId>> sorted_variables(const ground::GroundTask &task) {
    std::vector<std::vector<ground::FactId>> vars;
    std::vector<bool> grouped(task.num_facts(), false);
    for (const auto &group : task.mutex_groups) {
        if (group.empty())
            continue;
        vars.push_back(group);
        for (ground::FactId f : group)
            grouped[f] = true;
    }
    for (ground::FactId f = 0; f < task.num_facts(); ++f)
        if (!grouped[f])
            vars.push_back({f});
    std::vector<std::vector<std::string>> keys;
    for (const std::string &name : task.fact_names)
        keys.push_back(atom_key(name));
    auto by_name = [&](ground::FactId a, ground::FactId b) { return keys[a] < keys[b]; };
    for (auto &var : vars)
        std::sort(var.begin(), var.end(), by_name);
    std::sort(vars.begin(), vars.end(), [&](const auto &a, const auto &b) {
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), by_name);
    });
    return vars;
}

std::vector<bool> always_true_facts(const ground::GroundTask &task) {
    std::vector<bool> result(task.num_facts(), false);
    for (ground::FactId f : task.initial_state)
        result[f] = true;
    for (const ground::GroundOperator &op : task.operators)
        for (ground::FactId f : op.del)
            result[f] = false;
    return result;
}

// FD's causal graph weights: one unit per operator, precondition variable and changed
// variable (variable_order.py, weight_graph_from_ops).
Graph causal_graph(const ground::GroundTask &task, const std::vector<int> &var_of,
                   const std::vector<bool> &always_true) {
    Graph graph(task.num_facts() == 0 ? 0 : *std::max_element(var_of.begin(), var_of.end()) + 1);
    for (const ground::GroundOperator &op : task.operators) {
        std::set<int> pre_vars, changed;
        for (ground::FactId f : op.pre)
            if (!always_true[f])
                pre_vars.insert(var_of[f]);
        for (ground::FactId f : op.add)
            if (!always_true[f] && !std::binary_search(op.pre.begin(), op.pre.end(), f))
                changed.insert(var_of[f]);
        for (ground::FactId f : op.del)
            changed.insert(var_of[f]);
        for (int target : changed)
            for (int source : pre_vars)
                if (source != target)
                    ++graph[source][target];
    }
    return graph;
}

// Tarjan's algorithm visiting successors in increasing order; components come out in
// topological order, members in stack order, as in FD's sccs.py. Iterative, because
// tasks can have many thousands of variables.
std::vector<std::vector<int>> strongly_connected_components(const Graph &graph) {
    const int n = static_cast<int>(graph.size());
    std::vector<int> index(n, -1), low(n, 0), stack_position(n, -1), stack;
    std::vector<bool> on_stack(n, false);
    std::vector<std::vector<int>> sccs;
    int counter = 0;
    struct Frame {
        int v;
        std::map<int, int>::const_iterator next;
    };
    std::vector<Frame> frames;
    auto enter = [&](int v) {
        index[v] = low[v] = counter++;
        stack_position[v] = static_cast<int>(stack.size());
        stack.push_back(v);
        on_stack[v] = true;
        frames.push_back({v, graph[v].begin()});
    };
    for (int root = 0; root < n; ++root) {
        if (index[root] >= 0)
            continue;
        enter(root);
        while (!frames.empty()) {
            Frame &frame = frames.back();
            int v = frame.v;
            if (frame.next != graph[v].end()) {
                int w = (frame.next++)->first;
                if (index[w] < 0)
                    enter(w);
                else if (on_stack[w])
                    low[v] = std::min(low[v], index[w]);
                continue;
            }
            if (low[v] == index[v]) {
                auto start = stack.begin() + stack_position[v];
                std::vector<int> scc(start, stack.end());
                for (int w : scc)
                    on_stack[w] = false;
                stack.erase(start, stack.end());
                sccs.push_back(scc);
            }
            frames.pop_back();
            if (!frames.empty())
                low[frames.back().v] = std::min(low[frames.back().v], low[v]);
        }
    }
    std::reverse(sccs.begin(), sccs.end());
    return sccs;
}

// FD's MaxDAG: repeatedly take a node of minimum remaining incoming weight (ties in input
// order, lazily updated), then subtract its outgoing weights.
std::vector<int> max_dag(const std::map<int, std::vector<std::pair<int, int>>> &edges,
                         const std::vector<int> &input_order) {
    std::map<int, long long> incoming;
    for (const auto &[source, targets] : edges)
        for (const auto &[target, weight] : targets)
            incoming[target] += weight;
    std::map<long long, std::deque<int>> weight_to_nodes;
    for (int node : input_order)
        weight_to_nodes[incoming[node]].push_back(node);
    std::set<int> done;
    std::vector<int> result;
    while (!weight_to_nodes.empty()) {
        auto first = weight_to_nodes.begin();
        long long min_key = first->first;
        std::deque<int> &entries = first->second;
        int min_elem = -1;
        while (!entries.empty() &&
               (min_elem < 0 || done.count(min_elem) || min_key > incoming[min_elem])) {
            min_elem = entries.front();
            entries.pop_front();
        }
        if (entries.empty())
            weight_to_nodes.erase(first);
        if (min_elem < 0 || done.count(min_elem))
            continue;
        done.insert(min_elem);
        result.push_back(min_elem);
        auto it = edges.find(min_elem);
        if (it == edges.end())
            continue;
        for (const auto &[target, raw_weight] : it->second) {
            int weight = raw_weight % GOAL_EDGE_BONUS;
            if (done.count(target) || weight == 0)
                continue;
            incoming[target] -= weight;
            weight_to_nodes[incoming[target]].push_back(target);
        }
    }
    return result;
}

std::vector<int> variable_order(const Graph &graph, const std::set<int> &goal_vars) {
    std::vector<int> order;
    for (const std::vector<int> &scc : strongly_connected_components(graph)) {
        if (scc.size() == 1) {
            order.push_back(scc[0]);
            continue;
        }
        std::set<int> members(scc.begin(), scc.end());
        std::map<int, std::vector<std::pair<int, int>>> edges;
        for (int var : scc) {
            auto &out = edges[var];
            for (const auto &[target, weight] : graph[var]) {
                if (!members.count(target))
                    continue;
                if (goal_vars.count(target)) // FD lists goal edges twice, once boosted
                    out.emplace_back(target, GOAL_EDGE_BONUS + weight);
                out.emplace_back(target, weight);
            }
        }
        std::vector<int> part = max_dag(edges, scc);
        order.insert(order.end(), part.begin(), part.end());
    }
    return order;
}

} // namespace

FdOrder compute_fd_order(const ground::GroundTask &task) {
    std::vector<std::vector<ground::FactId>> vars = sorted_variables(task);
    std::vector<int> var_of(task.num_facts()), value_of(task.num_facts());
    for (int v = 0; v < static_cast<int>(vars.size()); ++v)
        for (int i = 0; i < static_cast<int>(vars[v].size()); ++i) {
            var_of[vars[v][i]] = v;
            value_of[vars[v][i]] = i;
        }
    std::set<int> goal_vars;
    for (ground::FactId f : task.goal)
        goal_vars.insert(var_of[f]);
    std::vector<bool> always_true = always_true_facts(task);
    std::vector<int> order = variable_order(causal_graph(task, var_of, always_true), goal_vars);
    std::vector<int> position(vars.size());
    for (int i = 0; i < static_cast<int>(order.size()); ++i)
        position[order[i]] = i;

    FdOrder result;
    result.always_true = always_true;
    result.fact_variable.resize(task.num_facts());
    for (ground::FactId f = 0; f < task.num_facts(); ++f)
        result.fact_variable[f] = position[var_of[f]];
    std::vector<ground::FactId> facts(task.num_facts());
    std::iota(facts.begin(), facts.end(), 0);
    std::sort(facts.begin(), facts.end(), [&](ground::FactId a, ground::FactId b) {
        return std::tuple(always_true[a], result.fact_variable[a], value_of[a]) <
               std::tuple(always_true[b], result.fact_variable[b], value_of[b]);
    });
    result.fact_rank.resize(task.num_facts());
    for (int r = 0; r < task.num_facts(); ++r)
        result.fact_rank[facts[r]] = r;
    // FD's sas_tasks.py sorts operators by name ("(load-truck p1 t1 s0)"), byte-wise.
    result.operators.resize(task.num_operators());
    std::iota(result.operators.begin(), result.operators.end(), 0);
    std::stable_sort(result.operators.begin(), result.operators.end(),
                     [&](ground::OperatorId a, ground::OperatorId b) {
                         return task.operators[a].name < task.operators[b].name;
                     });
    return result;
}

} // namespace envdesign::heuristics
