#include "heuristics/lmcut_heuristic.h"

#include "heuristic_test_util.h"
#include "heuristics/hmax_heuristic.h"
#include "heuristics/lmcut_landmarks.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>

namespace envdesign::heuristics {
namespace {

using testing::evaluate;
using testing::make_task;
using testing::op;

using Cut = std::pair<std::vector<ground::OperatorId>, int>;

std::vector<Cut> cuts_of(LmCutLandmarks &lmcut, std::vector<ground::FactId> facts, int *h) {
    std::vector<Cut> cuts;
    *h = lmcut.compute(facts, [&](std::span<const ground::OperatorId> ops, int cost) {
        std::vector<ground::OperatorId> sorted(ops.begin(), ops.end());
        std::sort(sorted.begin(), sorted.end());
        cuts.emplace_back(sorted, cost);
    });
    return cuts;
}

// s -o0(3)-> a, s -o1(4)-> b, {a,b} -o2(5)-> g. h^max = 9, h+ = LM-cut = 12: cutting o2
// first, then b's achiever (the h^max supporter of o2), then a's.
TEST(LmCutLandmarks, ClassicExampleCutsInOrder) {
    auto task = make_task(4, {op({0}, {1}, 3), op({0}, {2}, 4), op({1, 2}, {3}, 5)}, {0}, {3});
    LmCutLandmarks lmcut(task);
    int h = 0;
    std::vector<Cut> cuts = cuts_of(lmcut, {0}, &h);
    EXPECT_EQ(h, 12);
    ASSERT_EQ(cuts.size(), 3U);
    EXPECT_EQ(cuts[0], Cut({2}, 5));
    EXPECT_EQ(cuts[1], Cut({1}, 4));
    EXPECT_EQ(cuts[2], Cut({0}, 3));
    HMaxHeuristic hmax(task);
    EXPECT_EQ(evaluate(hmax, task, {0}), 9);
}

// Each operator achieves two of three goals: h+ = 2, but LM-cut stops after one cut of cost
// 1 (the achievers of one goal), whatever the tie-breaking.
TEST(LmCutHeuristic, CanBeBelowHPlus) {
    auto task =
        make_task(4, {op({0}, {1, 2}, 1), op({0}, {2, 3}, 1), op({0}, {1, 3}, 1)}, {0}, {1, 2, 3});
    LmCutLandmarks lmcut(task);
    int h = 0;
    std::vector<Cut> cuts = cuts_of(lmcut, {0}, &h);
    EXPECT_EQ(h, 1);
    ASSERT_EQ(cuts.size(), 1U);
    EXPECT_EQ(cuts[0].first.size(), 2U);
}

TEST(LmCutHeuristic, OverlappingAchievers) {
    // o0 adds both goals for 2, o1 and o2 one each for 1: two cuts of cost 1, both with o0.
    auto task = make_task(3, {op({0}, {1, 2}, 2), op({0}, {1}, 1), op({0}, {2}, 1)}, {0}, {1, 2});
    LmCutLandmarks lmcut(task);
    int h = 0;
    std::vector<Cut> cuts = cuts_of(lmcut, {0}, &h);
    EXPECT_EQ(h, 2);
    ASSERT_EQ(cuts.size(), 2U);
    for (const Cut &cut : cuts) {
        EXPECT_EQ(cut.second, 1);
        EXPECT_EQ(cut.first.size(), 2U);
        EXPECT_EQ(cut.first[0], 0);
    }
}

TEST(LmCutHeuristic, ZeroCostOperatorBeforeACostlyOne) {
    auto task = make_task(3, {op({0}, {1}, 0), op({1}, {2}, 3)}, {0}, {2});
    LmCutLandmarks lmcut(task);
    int h = 0;
    std::vector<Cut> cuts = cuts_of(lmcut, {0}, &h);
    EXPECT_EQ(h, 3);
    ASSERT_EQ(cuts.size(), 1U);
    EXPECT_EQ(cuts[0], Cut({1}, 3));
}

// The zero-cost operator puts a into the goal zone, so the cut is the costly one before it.
TEST(LmCutHeuristic, ZeroCostOperatorInTheGoalZone) {
    auto task = make_task(3, {op({0}, {1}, 2), op({1}, {2}, 0)}, {0}, {2});
    LmCutLandmarks lmcut(task);
    int h = 0;
    std::vector<Cut> cuts = cuts_of(lmcut, {0}, &h);
    EXPECT_EQ(h, 2);
    ASSERT_EQ(cuts.size(), 1U);
    EXPECT_EQ(cuts[0], Cut({0}, 2));
}

// A zero-cost achiever of a goal-zone fact that is itself unreachable (x is never true):
// FD's pegsol case; it must neither crash nor count.
TEST(LmCutHeuristic, UnreachableZeroCostAchiever) {
    auto task = make_task(3, {op({0}, {2}, 4), op({1}, {2}, 0)}, {0}, {2});
    LmCutHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 4);
    EXPECT_EQ(evaluate(h, task, {1}), 0);
}

TEST(LmCutHeuristic, AllZeroCostsGiveZero) {
    auto task = make_task(3, {op({0}, {1}, 0), op({1}, {2}, 0)}, {0}, {2});
    LmCutHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 0);
}

TEST(LmCutHeuristic, DeadEndReportsNoCuts) {
    auto task = make_task(3, {op({0}, {1}, 1)}, {0}, {1, 2});
    LmCutLandmarks lmcut(task);
    int h = 0;
    EXPECT_TRUE(cuts_of(lmcut, {0}, &h).empty());
    EXPECT_EQ(h, DEAD_END);
    LmCutHeuristic adapter(task);
    EXPECT_EQ(evaluate(adapter, task, {0}), DEAD_END);
    EXPECT_EQ(evaluate(adapter, task, {1, 2}), 0);
}

TEST(LmCutHeuristic, GoalStateAndEmptyGoal) {
    auto task = make_task(2, {op({0}, {1}, 3)}, {0}, {1});
    LmCutHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0, 1}), 0);
    auto empty_goal = make_task(1, {op({}, {0}, 3)}, {}, {});
    LmCutHeuristic h2(empty_goal);
    EXPECT_EQ(evaluate(h2, empty_goal, {}), 0);
}

// Large costs exercise the heap mode of the exploration queue.
TEST(LmCutHeuristic, LargeCosts) {
    auto task =
        make_task(4, {op({0}, {1}, 3000), op({0}, {2}, 4000), op({1, 2}, {3}, 50000)}, {0}, {3});
    LmCutHeuristic h(task);
    EXPECT_EQ(evaluate(h, task, {0}), 57000);
    EXPECT_EQ(evaluate(h, task, {0, 1}), 54000);
}

// h+ by brute force over operator subsets: the cheapest subset whose relaxed closure of
// `facts` contains the goal.
int h_plus(const ground::GroundTask &task, const std::vector<ground::FactId> &facts) {
    int best = DEAD_END;
    int n = task.num_operators();
    for (int mask = 0; mask < (1 << n); ++mask) {
        std::vector<bool> reached(task.num_facts(), false);
        for (ground::FactId f : facts)
            reached[f] = true;
        for (bool changed = true; changed;) {
            changed = false;
            for (int o = 0; o < n; ++o) {
                if (!(mask >> o & 1))
                    continue;
                const auto &pre = task.operators[o].pre;
                if (!std::all_of(pre.begin(), pre.end(), [&](int p) { return reached[p]; }))
                    continue;
                for (ground::FactId a : task.operators[o].add)
                    if (!reached[a])
                        reached[a] = changed = true;
            }
        }
        if (!std::all_of(task.goal.begin(), task.goal.end(), [&](int g) { return reached[g]; }))
            continue;
        int cost = 0;
        for (int o = 0; o < n; ++o)
            if (mask >> o & 1)
                cost += task.operators[o].cost;
        best = std::min(best, cost);
    }
    return best;
}

ground::GroundTask random_task(std::mt19937 &rng) {
    const int facts = 6;
    std::uniform_int_distribution<int> fact(0, facts - 1), cost(0, 4), size(0, 2);
    std::vector<ground::GroundOperator> ops;
    for (int o = 0; o < 9; ++o) {
        auto pick = [&](int count) {
            std::vector<ground::FactId> out;
            for (int i = 0; i < count; ++i)
                out.push_back(fact(rng));
            std::sort(out.begin(), out.end());
            out.erase(std::unique(out.begin(), out.end()), out.end());
            return out;
        };
        ops.push_back(op(pick(size(rng)), pick(1 + size(rng)), cost(rng)));
    }
    return make_task(facts, ops, {0}, {4, 5});
}

// hmax <= LM-cut <= h+, the cut costs are positive and sum to the estimate, and the three
// agree on dead ends, on random tasks with zero costs and operators without preconditions.
TEST(LmCutHeuristic, BoundedByHMaxAndHPlusOnRandomTasks) {
    std::mt19937 rng(42);
    int strictly_above_hmax = 0;
    for (int round = 0; round < 300; ++round) {
        ground::GroundTask task = random_task(rng);
        LmCutLandmarks lmcut(task);
        HMaxHeuristic hmax(task);
        for (std::vector<ground::FactId> state : {std::vector<int>{0}, {0, 1}, {2, 3}}) {
            int h = 0;
            std::vector<Cut> cuts = cuts_of(lmcut, state, &h);
            int hm = evaluate(hmax, task, state);
            int hp = h_plus(task, state);
            ASSERT_EQ(h == DEAD_END, hp == DEAD_END);
            ASSERT_EQ(hm == DEAD_END, hp == DEAD_END);
            if (h == DEAD_END)
                continue;
            int sum = 0;
            for (const Cut &cut : cuts) {
                ASSERT_GT(cut.second, 0);
                ASSERT_FALSE(cut.first.empty());
                sum += cut.second;
            }
            ASSERT_EQ(sum, h);
            ASSERT_LE(hm, h);
            ASSERT_LE(h, hp);
            strictly_above_hmax += h > hm;
        }
    }
    EXPECT_GT(strictly_above_hmax, 20); // the test would not notice LM-cut == h^max
}

} // namespace
} // namespace envdesign::heuristics
