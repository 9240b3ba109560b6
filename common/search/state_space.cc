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

// Per state, its steps (indices into the steps), in one array: a million states' lists
// cost no allocation each.
struct Adjacency {
    std::vector<std::size_t> begin; // state s: list[begin[s] .. begin[s + 1])
    std::vector<int> list;

    Adjacency(std::size_t states, const std::vector<Step> &steps, bool outgoing)
        : begin(states + 1, 0), list(steps.size()) {
        for (const Step &s : steps)
            ++begin[(outgoing ? s.from : s.to) + 1];
        for (std::size_t i = 0; i < states; ++i)
            begin[i + 1] += begin[i];
        std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
        for (int i = 0; i < static_cast<int>(steps.size()); ++i)
            list[next[outgoing ? steps[i].from : steps[i].to]++] = i;
    }
};

// Least costs from `sources` along `adjacent` (`next` picks a step's far end).
template <typename Next>
std::vector<double> dijkstra(std::size_t states, const std::vector<StateID> &sources,
                             const Adjacency &adjacent, const std::vector<Step> &steps,
                             const ground::GroundTask &task, Next next) {
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
        for (std::size_t k = adjacent.begin[s]; k < adjacent.begin[s + 1]; ++k) {
            const Step &step = steps[adjacent.list[k]];
            StateID t = next(step);
            double through = c + task.operators[step.op].cost;
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
        if (registry.size() > max_states || steps.size() > 8 * max_states ||
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
    auto g = dijkstra(n, {init}, Adjacency(n, steps, true), steps, task,
                      [](const Step &s) { return s.to; });
    auto h = dijkstra(n, goals, Adjacency(n, steps, false), steps, task,
                      [](const Step &s) { return s.from; });
    std::vector<double> through(task.num_operators(), INF);
    for (const Step &s : steps) {
        double cost = g[s.from] + task.operators[s.op].cost + h[s.to];
        if (cost < through[s.op])
            through[s.op] = cost;
    }
    return through;
}

} // namespace envdesign::search
