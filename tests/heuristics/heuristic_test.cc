#include "heuristics/heuristic.h"

#include "heuristic_test_util.h"

#include <gtest/gtest.h>

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
