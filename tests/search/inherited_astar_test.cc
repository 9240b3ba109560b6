// A* with inherited LM-cut estimates (search/inherited_lmcut.h) against blind A*, an
// independent exact search (uniform cost on the same lexicographic costs): on seeded random
// STRIPS tasks with zero costs, secondary costs and dead ends, both find the same status,
// primary cost and secondary cost, and the plan found is valid at those costs.

#include "heuristics/make_heuristic.h"
#include "search/astar_search.h"
#include "search/inherited_lmcut.h"
#include "search_test_util.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace envdesign::search {
namespace {

// A task of `facts` facts whose operators need one to three facts (so LM-cut is not h^max).
ground::GroundTask random_strips_task(std::mt19937 &rng, int facts, int operators) {
    ground::GroundTask task = testing::make_task(facts);
    std::uniform_int_distribution<int> fact(0, facts - 1), cost(0, 3), few(1, 3), some(0, 2);
    auto pick = [&](int n) {
        std::set<ground::FactId> out;
        while (static_cast<int>(out.size()) < n)
            out.insert(fact(rng));
        return std::vector<ground::FactId>(out.begin(), out.end());
    };
    for (int o = 0; o < operators; ++o) {
        std::vector<ground::FactId> pre = pick(few(rng)), add = pick(few(rng) % 2 + 1), del;
        for (ground::FactId f : pick(some(rng)))
            if (std::find(add.begin(), add.end(), f) == add.end())
                del.push_back(f);
        testing::add_op(task, "(op" + std::to_string(o) + ")", pre, add, del, cost(rng), cost(rng));
    }
    task.initial_state = pick(few(rng) + 1);
    task.goal = pick(few(rng));
    task.has_action_costs = true;
    return task;
}

// The plan's (primary, secondary) cost, or (-1, -1) if it is not applicable or misses the goal.
std::pair<long long, long long> replayed_costs(const ground::GroundTask &task,
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

TEST(InheritedLmCutSearch, RandomTasksAgreeWithBlindSearch) {
    std::mt19937 rng(24);
    int solved = 0, unsolvable = 0;
    for (int seed = 0; seed < 300; ++seed) {
        SCOPED_TRACE(seed);
        ground::GroundTask task = random_strips_task(rng, 10, 14);
        SearchResult blind = astar(task, heuristics::HeuristicKind::BLIND);
        InheritedLmCut estimates(task);
        AStarSearch search(task, estimates);
        while (search.step() == SearchStatus::IN_PROGRESS) {
        }
        SearchResult inherited = search.result();
        ASSERT_EQ(inherited.status, blind.status);
        if (blind.status == SearchStatus::FAILED) {
            ++unsolvable;
            continue;
        }
        ++solved;
        EXPECT_EQ(inherited.cost, blind.cost);
        EXPECT_EQ(inherited.secondary_cost, blind.secondary_cost);
        EXPECT_EQ(replayed_costs(task, inherited.plan),
                  std::make_pair(inherited.cost, inherited.secondary_cost));
        // The path through astar() with inherit_cuts takes the same search.
        SearchResult via_astar = astar(task, heuristics::HeuristicKind::LMCUT, {}, true);
        EXPECT_EQ(via_astar.plan, inherited.plan);
    }
    EXPECT_GT(solved, 50); // both kinds of task occur
    EXPECT_GT(unsolvable, 10);
}

} // namespace
} // namespace envdesign::search
