// The one rule for numbers that enter (design/model/numbers.h), and the store's records checked
// with it when read back (issue 21).

#include "design/evaluation/evaluation_record.h"
#include "design/model/numbers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace envdesign::design {
namespace {

const double NaN = std::numeric_limits<double>::quiet_NaN();

TEST(Numbers, FiniteAndInRangeOnly) {
    EXPECT_FALSE(number_problem(0, WEIGHT));
    EXPECT_FALSE(number_problem(1e6, WEIGHT));
    EXPECT_TRUE(number_problem(1e6 + 1, WEIGHT));
    EXPECT_TRUE(number_problem(-1e-300, WEIGHT));
    EXPECT_TRUE(number_problem(NaN, WEIGHT));
    EXPECT_TRUE(number_problem(INF, WEIGHT));
    EXPECT_TRUE(number_problem(1e25, WEIGHT));
    EXPECT_FALSE(number_problem(-1e9, MODIFICATION_COST));
    EXPECT_TRUE(number_problem(-1e308, MODIFICATION_COST));
    EXPECT_EQ(*number_problem(1e25, WEIGHT), "must be a number in [0, 1e+06] (got 1e+25)");
}

TEST(Numbers, PlanCostsAreThirtyTwoBitCostsOrNoPlan) {
    EXPECT_TRUE(valid_plan_cost(0));
    EXPECT_TRUE(valid_plan_cost(2147483647.0));
    EXPECT_TRUE(valid_plan_cost(INF));
    EXPECT_FALSE(valid_plan_cost(1e308));
    EXPECT_FALSE(valid_plan_cost(-INF));
    EXPECT_FALSE(valid_plan_cost(NaN));
    EXPECT_FALSE(valid_plan_cost(-1));
}

TaskExplicability solved_example() {
    TaskExplicability e;
    e.status = ExplicabilityStatus::SOLVED;
    e.ie = std::exp(2.0);
    e.robot_cost = 5;
    e.human_plan_cost = 6;
    e.human_optimal_cost = 4;
    e.plan = {"(move a b)"};
    return e;
}

TEST(Numbers, EvaluationsWithValuesNoPlannerGives) {
    EXPECT_FALSE(evaluation_problem(solved_example()));
    auto with = [](auto change) {
        TaskExplicability e = solved_example();
        change(e);
        return evaluation_problem(e).has_value();
    };
    EXPECT_TRUE(with([](TaskExplicability &e) { e.ie = NaN; }));
    EXPECT_TRUE(with([](TaskExplicability &e) { e.ie = -1; }));
    EXPECT_TRUE(with([](TaskExplicability &e) { e.robot_cost = 1e308; }));
    EXPECT_TRUE(with([](TaskExplicability &e) { e.robot_cost = INF; })); // solved: has a plan
    EXPECT_TRUE(with([](TaskExplicability &e) { e.human_optimal_cost = NaN; }));
    EXPECT_TRUE(with([](TaskExplicability &e) { e.status = ExplicabilityStatus::LIMIT; }));
    EXPECT_TRUE(with([](TaskExplicability &e) { e.status = ExplicabilityStatus::INEXPLICABLE; }));
    EXPECT_FALSE(with([](TaskExplicability &e) { e.ie = INF; })); // exp of a large gap
    EXPECT_FALSE(with([](TaskExplicability &e) {
        e.status = ExplicabilityStatus::INEXPLICABLE;
        e.ie = INF;
        e.robot_cost = INF;
    }));
}

TEST(Numbers, StoredRecordsAreCheckedWhenRead) {
    TaskExplicability good = solved_example();
    ASSERT_TRUE(decode_evaluation(encode_evaluation(good)));
    TaskExplicability bad = solved_example();
    bad.ie = NaN;
    EXPECT_FALSE(decode_evaluation(encode_evaluation(bad)));
    bad = solved_example();
    bad.human_plan_cost = 1e308;
    EXPECT_FALSE(decode_evaluation(encode_evaluation(bad)));
    EXPECT_EQ(decode_robot_bound(encode_robot_bound({12, std::nullopt}))->cost, 12);
    EXPECT_EQ(decode_robot_bound(encode_robot_bound({INF, std::nullopt}))->cost, INF);
    EXPECT_FALSE(decode_robot_bound(encode_robot_bound({1e308, std::nullopt})));
    EXPECT_FALSE(decode_robot_bound(encode_robot_bound({NaN, std::nullopt})));
    EXPECT_EQ(decode_robot_bound(encode_robot_bound({12, INF}))->ie_floor, INF); // exp overflows
    EXPECT_FALSE(decode_robot_bound(encode_robot_bound({12, -1.0})));
    EXPECT_FALSE(decode_robot_bound(encode_robot_bound({12, NaN})));
}

} // namespace
} // namespace envdesign::design
