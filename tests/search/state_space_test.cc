#include "search/state_space.h"

#include "search/astar_search.h"
#include "search_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace envdesign::search {
namespace {

using testing::add_op;
using testing::make_task;

// Two robots on one small graph each (two mutex groups), a step moves one of them and may
// need the other somewhere: not a graph search, so the state space is a real product.
ground::GroundTask random_two_robot_task(std::mt19937 &random) {
    int places = 2 + static_cast<int>(random() % 4);
    ground::GroundTask task = make_task(2 * places);
    std::vector<ground::FactId> first, second;
    for (int p = 0; p < places; ++p)
        first.push_back(p), second.push_back(places + p);
    task.mutex_groups = {first, second};
    int ops = static_cast<int>(random() % (3 * places + 1));
    for (int i = 0; i < ops; ++i) {
        int robot = static_cast<int>(random() % 2) * places;
        int from = robot + static_cast<int>(random() % places);
        int to = robot + static_cast<int>(random() % places);
        std::vector<ground::FactId> pre{from};
        if (random() % 3 == 0) // the other robot must be at some place
            pre.push_back((places - robot) + static_cast<int>(random() % places));
        std::sort(pre.begin(), pre.end());
        add_op(task, "(op" + std::to_string(i) + ")", pre, {to},
               from == to ? std::vector<ground::FactId>{} : std::vector<ground::FactId>{from},
               static_cast<int>(random() % 6));
    }
    task.initial_state = {0, places};
    task.goal = {static_cast<ground::FactId>(random() % places),
                 static_cast<ground::FactId>(places + random() % places)};
    std::sort(task.goal.begin(), task.goal.end());
    return task;
}

// The slow way the explored answer must match: A* on the task with one more fact that only
// operator o sets and the goal requires.
double least_cost_with_flag(const ground::GroundTask &task, ground::OperatorId o) {
    ground::GroundTask flagged = task;
    ground::FactId flag = flagged.num_facts();
    flagged.fact_names.push_back("(flag)");
    flagged.operators[o].add.push_back(flag);
    flagged.goal.push_back(flag);
    SearchResult result = astar(flagged, heuristics::HeuristicKind::LMCUT);
    if (result.status == SearchStatus::FAILED)
        return INFINITY;
    EXPECT_EQ(result.status, SearchStatus::SOLVED);
    return static_cast<double>(result.cost);
}

TEST(StateSpace, LeastCostThroughEachOperatorAgreesWithAFlaggedSearch) {
    std::mt19937 random(11);
    int reachable = 0, unreachable = 0;
    for (int trial = 0; trial < 150; ++trial) {
        ground::GroundTask task = random_two_robot_task(random);
        auto through = least_cost_through_operators(task, 1000, [] { return false; });
        ASSERT_TRUE(through.has_value());
        for (int o = 0; o < task.num_operators(); ++o) {
            double expected = least_cost_with_flag(task, o);
            ASSERT_EQ((*through)[o], expected) << "trial " << trial << ", operator " << o;
            (std::isinf(expected) ? unreachable : reachable) += 1;
        }
    }
    EXPECT_GT(reachable, 100); // both kinds of answer were tried
    EXPECT_GT(unreachable, 100);
}

TEST(StateSpace, TooManyStatesOrAStopGivesNothing) {
    // A chain of 30 independent switches: 2^30 states.
    ground::GroundTask task = make_task(30);
    for (int f = 0; f < 30; ++f)
        add_op(task, "(on" + std::to_string(f) + ")", {}, {f}, {});
    task.goal = {29};
    EXPECT_FALSE(least_cost_through_operators(task, 5000, [] { return false; }).has_value());
    EXPECT_FALSE(least_cost_through_operators(task, 1u << 31, [] { return true; }).has_value());
    ground::GroundTask small = make_task(3);
    add_op(small, "(a)", {}, {1}, {}, 2);
    add_op(small, "(b)", {1}, {2}, {}, 3);
    add_op(small, "(c)", {2}, {0}, {}, 1);
    small.goal = {2};
    auto through = least_cost_through_operators(small, 100, [] { return false; });
    ASSERT_TRUE(through.has_value());
    EXPECT_EQ((*through)[0], 5.0);
    EXPECT_EQ((*through)[1], 5.0);
    EXPECT_EQ((*through)[2], 6.0); // (c) after the goal, then nothing undoes it
}

} // namespace
} // namespace envdesign::search
