#include "search/state_space.h"

#include "search/state_registry.h"
#include "search/successor_generator.h"

#include <limits>
#include <queue>
#include <utility>

namespace envdesign::search {
namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

struct Step {
    StateID from;
    ground::OperatorId op;
    StateID to;
};

// Least costs from `sources` along `adjacent` (per state, its steps; `next` picks the far end).
template <typename Next>
std::vector<double> dijkstra(std::size_t states, const std::vector<StateID> &sources,
                             const std::vector<std::vector<int>> &adjacent,
                             const std::vector<Step> &steps, const ground::GroundTask &task,
                             Next next) {
    std::vector<double> cost(states, INF);
    using Entry = std::pair<double, StateID>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (StateID s : sources)
        cost[s] = 0, queue.push({0.0, s});
    while (!queue.empty()) {
        auto [c, s] = queue.top();
        queue.pop();
        if (c > cost[s])
            continue;
        for (int i : adjacent[s]) {
            StateID t = next(steps[i]);
            double through = c + task.operators[steps[i].op].cost;
            if (through < cost[t])
                cost[t] = through, queue.push({through, t});
        }
    }
    return cost;
}

} // namespace

std::optional<std::vector<double>> least_cost_through_operators(const ground::GroundTask &task,
                                                                std::size_t max_states,
                                                                const std::function<bool()> &stop) {
    StateRegistry registry(task);
    SuccessorGenerator generator(task);
    UnpackedState state(registry.codec());
    std::vector<ground::OperatorId> applicable;
    std::vector<Step> steps;
    std::vector<StateID> goals;
    StateID init = registry.insert_facts(task.initial_state).id;
    // Registered states are numbered in order, so the next one to expand is `expanded`.
    for (StateID expanded = 0; expanded < registry.size(); ++expanded) {
        if (registry.size() > max_states || steps.size() > 64 * max_states ||
            (expanded % 4096 == 0 && stop()))
            return std::nullopt;
        registry.unpack(expanded, state);
        bool goal = true;
        for (ground::FactId f : task.goal)
            goal = goal && state.holds(f);
        if (goal)
            goals.push_back(expanded);
        generator.applicable_operators(state, applicable);
        for (ground::OperatorId op : applicable)
            steps.push_back({expanded, op, registry.insert_successor(expanded, op).id});
    }
    std::size_t n = registry.size();
    std::vector<std::vector<int>> out(n), in(n);
    for (int i = 0; i < static_cast<int>(steps.size()); ++i) {
        out[steps[i].from].push_back(i);
        in[steps[i].to].push_back(i);
    }
    auto g = dijkstra(n, {init}, out, steps, task, [](const Step &s) { return s.to; });
    auto h = dijkstra(n, goals, in, steps, task, [](const Step &s) { return s.from; });
    std::vector<double> through(task.num_operators(), INF);
    for (const Step &s : steps) {
        double cost = g[s.from] + task.operators[s.op].cost + h[s.to];
        if (cost < through[s.op])
            through[s.op] = cost;
    }
    return through;
}

} // namespace envdesign::search
