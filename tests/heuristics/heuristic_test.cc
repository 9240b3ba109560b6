#include "heuristics/heuristic.h"

#include "heuristic_test_util.h"
#include "heuristics/hmax_heuristic.h"
#include "heuristics/lmcut_heuristic.h"
#include "heuristics/make_heuristic.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace envdesign::heuristics {
namespace {

using testing::evaluate;
using testing::make_task;
using testing::op;

TEST(ParseHeuristicKind, KnownNames) {
    EXPECT_EQ(parse_heuristic_kind("lmcut"), HeuristicKind::LMCUT);
    EXPECT_EQ(parse_heuristic_kind("hmax"), HeuristicKind::HMAX);
    EXPECT_EQ(parse_heuristic_kind("blind"), HeuristicKind::BLIND);
    EXPECT_EQ(heuristic_kind_name(HeuristicKind::LMCUT), "lmcut");
}

TEST(ParseHeuristicKind, UnknownNamesThrow) {
    EXPECT_THROW(parse_heuristic_kind("ff"), std::invalid_argument);
    EXPECT_THROW(parse_heuristic_kind("LMCUT"), std::invalid_argument);
    EXPECT_THROW(parse_heuristic_kind(""), std::invalid_argument);
}

// Two independent goals of cost 3 and 4: the kinds must differ exactly as theory says.
TEST(MakeHeuristic, EachKindGivesItsOwnValue) {
    auto task = make_task(3, {op({0}, {1}, 3), op({0}, {2}, 4)}, {0}, {1, 2});
    EXPECT_EQ(evaluate(*make_heuristic(HeuristicKind::BLIND, task), task, {0}), 3);
    EXPECT_EQ(evaluate(*make_heuristic(HeuristicKind::HMAX, task), task, {0}), 4);
    EXPECT_EQ(evaluate(*make_heuristic(HeuristicKind::LMCUT, task), task, {0}), 7);
}

// make_heuristic gives h^max for LM-cut on route graphs (every operator needs one fact, one
// goal fact) because the two agree there: checked on random graphs, zero costs and dead
// ends included, at every single-fact state and at random sets of facts.
TEST(MakeHeuristic, LmCutEqualsHMaxOnRouteGraphs) {
    std::mt19937 random(7);
    int compared = 0;
    for (int trial = 0; trial < 200; ++trial) {
        int places = 2 + static_cast<int>(random() % 12);
        std::vector<ground::GroundOperator> ops;
        int edges = static_cast<int>(random() % (places * 3));
        for (int e = 0; e < edges; ++e) {
            int from = static_cast<int>(random() % places),
                to = static_cast<int>(random() % places);
            if (random() % 8 == 0)
                ops.push_back(op({}, {to}, static_cast<int>(random() % 5)));
            else
                ops.push_back(op({from}, {to}, static_cast<int>(random() % 10), {from}));
        }
        ground::FactId goal = static_cast<ground::FactId>(random() % places);
        auto task = make_task(places, ops, {0}, {goal});
        LmCutHeuristic lmcut(task);
        HMaxHeuristic hmax(task);
        for (int p = 0; p < places; ++p) {
            std::vector<ground::FactId> state{p};
            if (random() % 3 == 0)
                state.push_back((p + 1 + static_cast<int>(random() % places)) % places);
            state.erase(std::unique(state.begin(), state.end()), state.end());
            ASSERT_EQ(evaluate(lmcut, task, state), evaluate(hmax, task, state))
                << "trial " << trial << ", place " << p;
            ++compared;
        }
    }
    EXPECT_GT(compared, 1000);
}

TEST(BlindHeuristic, ZeroInGoalStatesElseCheapestOperator) {
    auto task = make_task(3, {op({0}, {1}, 5), op({1}, {2}, 2), op({2}, {0}, 9)}, {0}, {2});
    auto h = make_heuristic(HeuristicKind::BLIND, task);
    EXPECT_EQ(evaluate(*h, task, {0}), 2);
    EXPECT_EQ(evaluate(*h, task, {1}), 2);
    EXPECT_EQ(evaluate(*h, task, {2}), 0);
    EXPECT_EQ(evaluate(*h, task, {0, 2}), 0);
}

TEST(BlindHeuristic, ZeroCostOperatorsGiveZero) {
    auto task = make_task(2, {op({0}, {1}, 0), op({0}, {1}, 4)}, {0}, {1});
    EXPECT_EQ(evaluate(*make_heuristic(HeuristicKind::BLIND, task), task, {0}), 0);
}

} // namespace
} // namespace envdesign::heuristics
