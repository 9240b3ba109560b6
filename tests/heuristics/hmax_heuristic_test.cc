#include "heuristics/hmax_heuristic.h"

#include "heuristic_test_util.h"

#include <gtest/gtest.h>

namespace envdesign::heuristics {
namespace {

using testing::evaluate;
using testing::make_task;
using testing::op;

// Facts: 0 a, 1 b, 2 c, 3 d, 4 x. a->b (2), b->c (3), a->c (7), c->d (1), a->x (10),
// {b,x}->d (0).
ground::GroundTask chain_task(std::vector<ground::FactId> goal) {
    return make_task(5,
                     {op({0}, {1}, 2), op({1}, {2}, 3), op({0}, {2}, 7), op({2}, {3}, 1),
                      op({0}, {4}, 10), op({1, 4}, {3}, 0)},
                     {0}, std::move(goal));
}

TEST(HMaxHeuristic, CheapestPathThroughAChain) {
    auto task = chain_task({3});
    HMaxHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 6); // a-b-c-d: 2 + 3 + 1 beats a-c-d: 7 + 1
    EXPECT_EQ(evaluate(h, task, {1}), 4);
    EXPECT_EQ(evaluate(h, task, {2}), 1);
    EXPECT_EQ(evaluate(h, task, {3}), 0);
}

TEST(HMaxHeuristic, ConjunctionsCostTheirMaximum) {
    auto task = chain_task({1, 2, 4});
    HMaxHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 10); // max(2, 5, 10)
    EXPECT_EQ(evaluate(h, task, {0, 4}), 5);
    // From {b, x} the zero-cost {b,x}->d and c via b->c.
    auto goal_d = chain_task({3, 4});
    HMaxHeuristic hd(goal_d);
    EXPECT_EQ(evaluate(hd, goal_d, {1, 4}), 0);
}

TEST(HMaxHeuristic, UnreachableGoalIsADeadEnd) {
    auto task = chain_task({0});
    HMaxHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {1}), DEAD_END); // nothing adds a
    EXPECT_EQ(evaluate(h, task, {0}), 0);
}

TEST(HMaxHeuristic, OperatorsWithoutPreconditionsAndEmptyGoal) {
    auto task = make_task(2, {op({}, {0}, 4), op({0}, {1}, 1)}, {}, {1});
    HMaxHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {}), 5);
    auto empty_goal = make_task(1, {op({}, {0}, 4)}, {}, {});
    HMaxHeuristic h2(empty_goal);
    EXPECT_EQ(evaluate(h2, empty_goal, {}), 0);
}

TEST(HMaxHeuristic, RepeatedCallsDoNotLeakState) {
    auto task = chain_task({3});
    HMaxHeuristic h(task);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(evaluate(h, task, {0}), 6);
        EXPECT_EQ(evaluate(h, task, {4}), DEAD_END);
        EXPECT_EQ(evaluate(h, task, {1, 4}), 0);
    }
}

// Large costs switch the exploration queue to its heap mode; values must not change.
TEST(HMaxHeuristic, LargeCosts) {
    auto task = make_task(
        4, {op({0}, {1}, 1000), op({1}, {2}, 2500), op({0}, {2}, 4000), op({2}, {3}, 123456)}, {0},
        {3});
    HMaxHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 3500 + 123456);
}

} // namespace
} // namespace envdesign::heuristics
