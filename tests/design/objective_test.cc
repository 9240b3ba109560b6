// The objective, its lower bound and the ranking, with every expected value worked out by
// hand in the comments.

#include "design/objective/objective.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envdesign::design {
namespace {

TaskExplicability solved_with(double ie, double robot_cost) {
    TaskExplicability t;
    t.status = ExplicabilityStatus::SOLVED;
    t.ie = ie;
    t.robot_cost = robot_cost;
    return t;
}

TaskExplicability inexplicable() {
    TaskExplicability t;
    t.status = ExplicabilityStatus::INEXPLICABLE;
    return t;
}

DesignProblem two_tasks(double p0, double p1, ObjectiveWeights w) {
    DesignProblem problem;
    problem.tasks.resize(2);
    problem.tasks[0].probability = p0;
    problem.tasks[1].probability = p1;
    problem.weights = w;
    return problem;
}

// gamma = 0.9, T = 10: (1 - 0.9^10) / 0.1 = (1 - 0.3486784401) * 10 = 6.513215599.
TEST(Objective, DiscountedHorizon) {
    EXPECT_NEAR(discounted_horizon({1, 1, 1, 0.9, 10}), 6.513215599, 1e-12);
    EXPECT_DOUBLE_EQ(discounted_horizon({1, 1, 1, 0.9, 1}), 1.0);
    EXPECT_DOUBLE_EQ(discounted_horizon({1, 1, 1, 1.0, 7}), 7.0);  // gamma = 1: T
    EXPECT_DOUBLE_EQ(discounted_horizon({1, 1, 1, 0.5, 3}), 1.75); // 1 + 0.5 + 0.25
    EXPECT_DOUBLE_EQ(discounted_horizon({1, 1, 1, 0.0, 5}), 1.0);  // only the first step
}

// Probabilities 0.25 / 0.75, IE 3 and 1, robot costs 8 and 4; alpha 2, beta 5, kappa 0.5,
// gamma 0.5, T 3, C = 1.5:
//   E[IE] = 0.75 + 0.75 = 1.5, f_T = 1.5 * 1.75 = 2.625
//   T * E[c_R] = 3 * (2 + 3) = 15
//   objective = 2 * 2.625 + 5 * 1.5 + 0.5 * 15 = 5.25 + 7.5 + 7.5 = 20.25
TEST(Objective, NonUniformProbabilitiesHorizonAndDiscount) {
    DesignProblem problem = two_tasks(0.25, 0.75, {2, 5, 0.5, 0.5, 3});
    Objective o = objective_of(problem, 1.5, {solved_with(3, 8), solved_with(1, 4)});
    EXPECT_DOUBLE_EQ(o.terms.inexplicability, 2.625);
    EXPECT_DOUBLE_EQ(o.terms.design_cost, 1.5);
    EXPECT_DOUBLE_EQ(o.terms.robot_cost, 15);
    EXPECT_DOUBLE_EQ(o.value, 20.25);
}

TEST(Objective, AnInexplicableTaskMakesItInfinite) {
    DesignProblem problem = two_tasks(0.5, 0.5, {1, 1, 1, 1, 1});
    EXPECT_TRUE(std::isinf(objective_of(problem, 0, {solved_with(1, 1), inexplicable()}).value));
    // ... unless it never happens.
    DesignProblem never = two_tasks(1, 0, {1, 1, 1, 1, 1});
    EXPECT_DOUBLE_EQ(objective_of(never, 0, {solved_with(2, 3), inexplicable()}).value, 5);
}

// Unknown tasks count with IE 1 (EXP_COST_DIFF) or 0 (COST_DIFF) and robot cost 0.
// Task 0 known (IE 3, cost 8, p 0.25), task 1 unknown (p 0.75), weights as above, C = 1.5:
//   EXP: E[IE] >= 0.75 + 0.75 = 1.5 -> 2 * 2.625 + 7.5 + 0.5 * 3 * 2 = 5.25 + 7.5 + 3 = 15.75
//   COST_DIFF: E[IE] >= 0.75 -> 2 * 1.3125 + 7.5 + 3 = 13.125
TEST(Objective, LowerBoundWithUnknownTasks) {
    DesignProblem problem = two_tasks(0.25, 0.75, {2, 5, 0.5, 0.5, 3});
    TaskExplicability known = solved_with(3, 8);
    EXPECT_DOUBLE_EQ(objective_lower_bound(problem, 1.5, {&known, nullptr}), 15.75);
    problem.weights.distance = Distance::COST_DIFF;
    EXPECT_DOUBLE_EQ(objective_lower_bound(problem, 1.5, {&known, nullptr}), 13.125);
    TaskExplicability bad = inexplicable();
    EXPECT_TRUE(std::isinf(objective_lower_bound(problem, 0, {nullptr, &bad})));
    // The bound never exceeds the objective once all is known.
    TaskExplicability other = solved_with(1, 4);
    EXPECT_LE(objective_lower_bound(problem, 1.5, {&known, &other}),
              objective_of(problem, 1.5, {known, other}).value + 1e-12);
}

// The explaining robot, task 1 unknown with robot bound 10, IE floor e^5 and explanation floor 3
// (weights as above, H = 1.75, explanation_cost 2): explaining 3 differences beats acting at
// e^5, so task 1 counts IE 1, robot cost 10 and 0.75 * 2 * 3 * 1.75 = 7.875 of explanation:
//   5.25 (IE, as above) + 7.5 + 0.5 * 3 * (0.25 * 8 + 0.75 * 10) + 7.875 = 34.875.
// Without the explanation floor, one difference: 0.75 * 2 * 1 * 1.75 = 2.625, so 29.625.
TEST(Objective, LowerBoundCountsTheExplanationFloor) {
    DesignProblem problem = two_tasks(0.25, 0.75, {2, 5, 0.5, 0.5, 3});
    problem.weights.behaviour = RobotBehaviour::EXPLAINING;
    problem.weights.explanation_cost = 2;
    TaskExplicability known = solved_with(3, 8);
    std::vector<std::optional<double>> robot = {std::nullopt, 10.0};
    std::vector<std::optional<double>> ie = {std::nullopt, std::exp(5.0)};
    EXPECT_DOUBLE_EQ(objective_lower_bound(problem, 1.5, {&known, nullptr}, robot, ie, {{}, 3}),
                     34.875);
    EXPECT_DOUBLE_EQ(objective_lower_bound(problem, 1.5, {&known, nullptr}, robot, ie), 29.625);
    // With an IE floor of e, acting (2 * 1.75 * 0.75 * e = 7.14) is cheaper than telling 3
    // (2.625 + 7.875 = 10.5), though not than telling one (5.25).
    std::vector<std::optional<double>> low = {std::nullopt, std::exp(1.0)};
    EXPECT_NEAR(objective_lower_bound(problem, 1.5, {&known, nullptr}, robot, low, {{}, 3}),
                2 * 1.75 * (0.75 + 0.75 * std::exp(1.0)) + 7.5 + 14.25, 1e-9);
    EXPECT_DOUBLE_EQ(objective_lower_bound(problem, 1.5, {&known, nullptr}, robot, low), 29.625);
}

TEST(Ranking, LowerObjectiveFirst) {
    EXPECT_TRUE(ranks_before({10, 5, {0, 1}}, {11, 0, {}}));
    EXPECT_FALSE(ranks_before({11, 0, {}}, {10, 5, {0, 1}}));
}

TEST(Ranking, TiesGoToFewerModificationsThenCheaperThenEarlier) {
    EXPECT_TRUE(ranks_before({10, 9, {3}}, {10, 1, {0, 1}}));    // fewer
    EXPECT_TRUE(ranks_before({10, 1, {2}}, {10, 2, {0}}));       // cheaper
    EXPECT_TRUE(ranks_before({10, 1, {0, 3}}, {10, 1, {1, 2}})); // earlier in spec order
    EXPECT_FALSE(ranks_before({10, 1, {1, 2}}, {10, 1, {0, 3}}));
}

TEST(Ranking, RoundingDoesNotBreakTies) {
    // 0.1 + 0.2 != 0.3 in binary; the two are still a tie, decided by the size.
    EXPECT_TRUE(ranks_before({0.1 + 0.2, 0, {}}, {0.3, 0, {0}}));
    EXPECT_TRUE(ranks_before({0.3, 0, {}}, {0.1 + 0.2, 0, {0}}));
}

TEST(Ranking, InfiniteNeverBeatsFinite) {
    EXPECT_TRUE(ranks_before({1e300, 100, {0, 1, 2}}, {INF, 0, {}}));
    EXPECT_FALSE(ranks_before({INF, 0, {}}, {1e300, 100, {0, 1, 2}}));
    EXPECT_TRUE(ranks_before({INF, 0, {}}, {INF, 0, {0}})); // among infinite ones: fewer
}

} // namespace
} // namespace envdesign::design
