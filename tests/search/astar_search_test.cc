#include "search/astar_search.h"

#include "heuristics/make_heuristic.h"
#include "search_test_util.h"

#include <gtest/gtest.h>

#include <map>

namespace envdesign::search {
namespace {

using heuristics::HeuristicKind;
using testing::Edge;
using testing::graph_task;
using testing::grid_task;

class AStarAllHeuristics : public ::testing::TestWithParam<HeuristicKind> {};

TEST_P(AStarAllHeuristics, GridWithWallFindsShortestPath) {
    // 5x5 grid, a wall in column 2 except its bottom cell: shortest paths run along the
    // bottom row, still 8 steps, and blind search must explore around the wall.
    ground::GroundTask task = grid_task(5, {2, 7, 12, 17});
    SearchResult result = astar(task, GetParam());
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 8);
    EXPECT_EQ(result.plan.size(), 8U);
    EXPECT_EQ(testing::replayed_costs(task, result.plan).first, 8); // valid, at that cost
    EXPECT_EQ(result.stats.bytes_per_state, 4U);
}

TEST_P(AStarAllHeuristics, WeightedGraphPrefersCheapDetour) {
    // 0 -> 3 directly costs 10; 0 -> 1 -> 2 -> 3 costs 3 + 3 + 3 = 9.
    ground::GroundTask task =
        graph_task(4, {{0, 3, 10}, {0, 1, 3}, {1, 2, 3}, {2, 3, 3}, {1, 3, 7}}, 0, 3);
    SearchResult result = astar(task, GetParam());
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 9);
    EXPECT_EQ(result.plan, (std::vector<ground::OperatorId>{1, 2, 3}));
    EXPECT_EQ(testing::replayed_costs(task, result.plan).first, result.cost);
}

TEST_P(AStarAllHeuristics, UnsolvableFails) {
    // The goal vertex 3 is only reachable from 2, which nothing reaches.
    ground::GroundTask task = graph_task(4, {{0, 1, 1}, {1, 0, 1}, {2, 3, 1}}, 0, 3);
    SearchResult result = astar(task, GetParam());
    EXPECT_EQ(result.status, SearchStatus::FAILED);
    EXPECT_TRUE(result.plan.empty());
}

TEST_P(AStarAllHeuristics, ZeroCostOperators) {
    // Free moves 0->1->2, then 2->3 costs 2; the direct 0->3 costs 3.
    ground::GroundTask task =
        graph_task(4, {{0, 1, 0}, {1, 2, 0}, {2, 3, 2}, {0, 3, 3}, {1, 0, 0}}, 0, 3);
    SearchResult result = astar(task, GetParam());
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 2);
    EXPECT_EQ(result.plan.size(), 3U);
}

TEST_P(AStarAllHeuristics, InitialStateIsGoal) {
    ground::GroundTask task = graph_task(2, {{0, 1, 1}}, 0, 0);
    SearchResult result = astar(task, GetParam());
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 0);
    EXPECT_TRUE(result.plan.empty());
    EXPECT_EQ(result.stats.expanded, 1); // the goal counts as expanded, as in FD
}

TEST_P(AStarAllHeuristics, SecondaryCostBreaksTies) {
    // Two plans of primary cost 4; the second is cheaper in secondary cost (1 vs 5). A third
    // plan has secondary cost 0 but primary cost 5.
    ground::GroundTask task = graph_task(
        5, {{0, 1, 2, 5}, {1, 4, 2, 0}, {0, 2, 2, 0}, {2, 4, 2, 1}, {0, 3, 1, 0}, {3, 4, 4, 0}}, 0,
        4);
    SearchResult result = astar(task, GetParam());
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 4);
    EXPECT_EQ(result.secondary_cost, 1);
    EXPECT_EQ(result.plan, (std::vector<ground::OperatorId>{2, 3}));
}

INSTANTIATE_TEST_SUITE_P(Kinds, AStarAllHeuristics,
                         ::testing::Values(HeuristicKind::BLIND, HeuristicKind::HMAX,
                                           HeuristicKind::LMCUT));

TEST(AStarSearch, InitialDeadEndFails) {
    ground::GroundTask task = graph_task(3, {{1, 2, 1}}, 0, 2);
    SearchResult result = astar(task, HeuristicKind::LMCUT);
    EXPECT_EQ(result.status, SearchStatus::FAILED);
    EXPECT_EQ(result.stats.expanded, 0);
    EXPECT_EQ(result.stats.dead_ends, 1);
}

TEST(AStarSearch, DeadEndsArePruned) {
    // 0 -> 1 leads into a trap (1 -> 2 only, 2 has no way to the goal 3); 0 -> 3 costs 5.
    ground::GroundTask task = graph_task(4, {{0, 1, 1}, {1, 2, 1}, {0, 3, 5}}, 0, 3);
    SearchResult result = astar(task, HeuristicKind::LMCUT);
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 5);
    EXPECT_EQ(result.stats.dead_ends, 1); // state 1 (LM-cut sees it is a dead end)
    EXPECT_EQ(result.stats.expanded, 2);  // 0 and the goal
    EXPECT_EQ(result.stats.evaluated, 3);
    EXPECT_EQ(result.stats.generated, 2);
}

// Admissible but inconsistent: h(a) = 6 is exact while h(s) = h(c) = 0. A* first closes c
// with g = 3 (via s -> c), then finds g = 2 via a and must reopen it to return cost 7.
class TableHeuristic : public heuristics::Heuristic {
public:
    explicit TableHeuristic(std::map<ground::FactId, int> h) : h_(std::move(h)) {}
    int compute(const heuristics::StateView &state) override { return h_[state.facts()[0]]; }

private:
    std::map<ground::FactId, int> h_;
};

TEST(AStarSearch, ReopensClosedStatesForInconsistentHeuristics) {
    // vertices: s 0, a 1, c 2, g 3
    ground::GroundTask task = graph_task(4, {{0, 1, 1}, {1, 2, 1}, {0, 2, 3}, {2, 3, 5}}, 0, 3);
    TableHeuristic h({{0, 0}, {1, 6}, {2, 0}, {3, 0}});
    AStarSearch search(task, h);
    while (search.step() == SearchStatus::IN_PROGRESS) {
    }
    SearchResult result = search.result();
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 7);
    EXPECT_EQ(result.plan, (std::vector<ground::OperatorId>{0, 1, 3}));
    EXPECT_EQ(result.stats.reopened, 1);
    EXPECT_EQ(result.stats.expanded, 5); // s, c, a, c again, g
}

// Where every operator's secondary cost equals its primary cost (P_mod when both models
// charge alike) each plan's two costs are equal, and the search orders by (f, h) alone: it
// follows the deep path within the last f layer (0, 1, 2, goal) instead of expanding that
// layer by secondary g (0, 1, 4, 2, 5, goal), and still reports the secondary cost.
TEST(AStarSearch, SecondaryCostsEqualToPrimaryAreNotSearched) {
    // 0 -> 1 -> 2 -> 3 and 0 -> 4 -> 5 -> 3, each step costing (1, 1); h is exact.
    ground::GroundTask task = graph_task(
        6, {{0, 1, 1, 1}, {1, 2, 1, 1}, {2, 3, 1, 1}, {0, 4, 1, 1}, {4, 5, 1, 1}, {5, 3, 1, 1}}, 0,
        3);
    TableHeuristic h({{0, 3}, {1, 2}, {2, 1}, {3, 0}, {4, 2}, {5, 1}});
    AStarSearch search(task, h);
    while (search.step() == SearchStatus::IN_PROGRESS) {
    }
    SearchResult result = search.result();
    ASSERT_EQ(result.status, SearchStatus::SOLVED);
    EXPECT_EQ(result.cost, 3);
    EXPECT_EQ(result.secondary_cost, 3);
    EXPECT_EQ(result.plan, (std::vector<ground::OperatorId>{0, 1, 2}));
    EXPECT_EQ(result.stats.expanded, 4);
}

// Each step expands one state; the initial evaluation is a step of its own.
TEST(AStarSearch, StepwiseCounts) {
    ground::GroundTask task = graph_task(3, {{0, 1, 1}, {1, 2, 1}}, 0, 2);
    auto h = heuristics::make_heuristic(HeuristicKind::BLIND, task);
    AStarSearch search(task, *h);
    EXPECT_EQ(search.step(), SearchStatus::IN_PROGRESS); // evaluates the initial state
    EXPECT_EQ(search.result().stats.expanded, 0);
    EXPECT_EQ(search.step(), SearchStatus::IN_PROGRESS);
    EXPECT_EQ(search.result().stats.expanded, 1);
    EXPECT_EQ(search.step(), SearchStatus::IN_PROGRESS);
    EXPECT_EQ(search.step(), SearchStatus::SOLVED);
    EXPECT_EQ(search.result().stats.expanded, 3);
    EXPECT_EQ(search.step(), SearchStatus::SOLVED); // stays finished
}

// The largest f expanded never passes the optimal cost, with an admissible heuristic that
// is not consistent either (LM-cut), and reaches it when the search ends: a search stopped at
// any step proves f_bound.
TEST(AStarSearch, FBoundIsALowerBoundAtEveryStep) {
    ground::GroundTask task = grid_task(6, {2, 8, 14, 20, 26});
    for (HeuristicKind kind : {HeuristicKind::BLIND, HeuristicKind::HMAX, HeuristicKind::LMCUT}) {
        SCOPED_TRACE(static_cast<int>(kind));
        long long optimal = astar(task, kind).cost;
        auto h = heuristics::make_heuristic(kind, task);
        AStarSearch search(task, *h);
        long long previous = 0;
        SearchStatus status;
        while ((status = search.step()) == SearchStatus::IN_PROGRESS) {
            long long bound = search.result().stats.f_bound;
            EXPECT_LE(bound, optimal);
            EXPECT_GE(bound, previous);
            previous = bound;
        }
        ASSERT_EQ(status, SearchStatus::SOLVED);
        EXPECT_EQ(search.result().stats.f_bound, optimal);
        EXPECT_GE(search.result().stats.f_bound, search.result().stats.initial_h);
    }
}

// 22 independent switches: 4 million states, far more than blind search can do in 0.2 s.
ground::GroundTask switches_task(int n) {
    ground::GroundTask task = testing::make_task(n + 1);
    for (int i = 0; i < n; ++i)
        testing::add_op(task, "(on " + std::to_string(i) + ")", {}, {i}, {});
    testing::add_op(task, "(never)", {0, n}, {n}, {}); // n is unreachable
    task.goal = {n};
    return task;
}

TEST(AStarSearch, TimeLimit) {
    ground::GroundTask task = switches_task(22);
    SearchResult result = astar(task, HeuristicKind::BLIND, {.time_limit_s = 0.2});
    EXPECT_EQ(result.status, SearchStatus::LIMIT);
    EXPECT_GT(result.stats.expanded, 0);
    EXPECT_LT(result.stats.search_seconds, 1.0);
}

TEST(AStarSearch, MemoryLimit) {
    ground::GroundTask task = switches_task(22);
    auto h = heuristics::make_heuristic(HeuristicKind::BLIND, task);
    AStarSearch search(task, *h, {.memory_limit_bytes = 4 << 20});
    SearchStatus status;
    while ((status = search.step()) == SearchStatus::IN_PROGRESS) {
    }
    EXPECT_EQ(status, SearchStatus::LIMIT);
    EXPECT_GE(search.memory_bytes(), 4U << 20);
    EXPECT_LT(search.memory_bytes(), 64U << 20);
}

// Exhaustive: the reachable space of 10 switches is 1024 states, all expanded before the
// search proves the goal unreachable.
TEST(AStarSearch, ExhaustsStateSpace) {
    ground::GroundTask task = switches_task(10);
    SearchResult result = astar(task, HeuristicKind::BLIND);
    EXPECT_EQ(result.status, SearchStatus::FAILED);
    EXPECT_EQ(result.stats.expanded, 1024);
    EXPECT_EQ(result.stats.registered_states, 1024);
}

} // namespace
} // namespace envdesign::search
