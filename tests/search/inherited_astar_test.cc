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

// Counts the successors that inherit a cut, to show that the cuts are passed on.
class CountingInheritedLmCut : public InheritedLmCut {
public:
    using InheritedLmCut::InheritedLmCut;
    int successor(StateID child, const UnpackedState &state, StateID parent,
                  ground::OperatorId op) override {
        inheriting += inherited(parent, op) > 0;
        return InheritedLmCut::successor(child, state, parent, op);
    }
    int inheriting = 0;
};

TEST(InheritedLmCutSearch, RandomTasksAgreeWithBlindSearch) {
    std::mt19937 rng(24);
    int solved = 0, unsolvable = 0, inheriting = 0;
    for (int seed = 0; seed < 300; ++seed) {
        SCOPED_TRACE(seed);
        ground::GroundTask task = random_strips_task(rng, 10, 14);
        SearchResult blind = astar(task, heuristics::HeuristicKind::BLIND);
        CountingInheritedLmCut estimates(task);
        AStarSearch search(task, estimates);
        while (search.step() == SearchStatus::IN_PROGRESS) {
        }
        SearchResult inherited = search.result();
        inheriting += estimates.inheriting;
        ASSERT_EQ(inherited.status, blind.status);
        if (blind.status == SearchStatus::FAILED) {
            ++unsolvable;
            continue;
        }
        ++solved;
        EXPECT_EQ(inherited.cost, blind.cost);
        EXPECT_EQ(inherited.secondary_cost, blind.secondary_cost);
        EXPECT_EQ(testing::replayed_costs(task, inherited.plan),
                  std::make_pair(inherited.cost, inherited.secondary_cost));
        // The path through astar() with inherit_cuts takes the same search.
        SearchResult via_astar = astar(task, heuristics::HeuristicKind::LMCUT, {}, true);
        EXPECT_EQ(via_astar.plan, inherited.plan);
    }
    EXPECT_GT(solved, 50); // both kinds of task occur
    EXPECT_GT(unsolvable, 10);
    EXPECT_GT(inheriting, 100); // successors did start from their parents' cuts
}

} // namespace
} // namespace envdesign::search
