// The independent validator on the tiny domain, whose optimal plan was worked out by hand:
// move kitchen->hub (2), unlock lab (5), move hub->lab (2) = 9.

#include "pddl/parser.h"
#include "validate/plan_validator.h"

#include <gtest/gtest.h>

namespace envdesign::validate {
namespace {

class PlanValidatorTest : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/tiny/";
        domain = pddl::parse_domain_file(dir + "domain.pddl");
        problem = pddl::parse_problem_file(dir + "problem.pddl", domain);
    }
    pddl::Domain domain;
    pddl::Problem problem;
};

TEST_F(PlanValidatorTest, AcceptsTheHandMadePlanWithItsCost) {
    Validation v = validate_plan(domain, problem,
                                 {"(move r1 kitchen hub)", "(unlock r1 lab)", "(move r1 hub lab)"});
    EXPECT_TRUE(v.valid) << v.error;
    EXPECT_EQ(v.cost, 9);
}

TEST_F(PlanValidatorTest, RejectsAStepIntoALockedRoom) {
    Validation v = validate_plan(domain, problem, {"(move r1 kitchen lab)"});
    EXPECT_FALSE(v.valid);
    EXPECT_EQ(v.failed_step, 0);
    EXPECT_NE(v.error.find("(not (locked ?to))"), std::string::npos) << v.error;
}

TEST_F(PlanValidatorTest, RejectsAPlanThatMissesTheGoal) {
    Validation v = validate_plan(domain, problem, {"(move r1 kitchen hub)"});
    EXPECT_FALSE(v.valid);
    EXPECT_NE(v.error.find("goal (at r1 lab)"), std::string::npos) << v.error;
}

TEST_F(PlanValidatorTest, RejectsUnknownActionsAndWrongTypes) {
    EXPECT_FALSE(validate_plan(domain, problem, {"(fly r1 lab)"}).valid);
    // r1 is a robot, not a place.
    EXPECT_FALSE(validate_plan(domain, problem, {"(move r1 r1 hub)"}).valid);
    // moving to the same place is excluded by (not (= ?from ?to)).
    EXPECT_FALSE(validate_plan(domain, problem, {"(move r1 kitchen kitchen)"}).valid);
}

// A step whose cost has no value in the problem is not applicable, as the grounder has it
// (tests/data/liberties/undefined-cost: the road a-c has no length).
TEST(PlanValidator, RejectsAStepWhoseCostHasNoValue) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/liberties/";
    pddl::Domain domain = pddl::parse_domain_file(dir + "undefined-cost-domain.pddl");
    pddl::Problem problem = pddl::parse_problem_file(dir + "undefined-cost-problem.pddl", domain);
    Validation direct = validate_plan(domain, problem, {"(drive a c)"});
    EXPECT_FALSE(direct.valid);
    EXPECT_EQ(direct.failed_step, 0);
    EXPECT_NE(direct.error.find("no value for (length a c)"), std::string::npos) << direct.error;
    Validation long_way = validate_plan(domain, problem, {"(drive a b)", "(drive b c)"});
    EXPECT_TRUE(long_way.valid) << long_way.error;
    EXPECT_EQ(long_way.cost, 7);
    // without the metric the cost terms are not read: the direct road is a step of cost 1
    pddl::Problem no_metric =
        pddl::parse_problem_file(dir + "undefined-cost-no-metric-problem.pddl", domain);
    Validation unit = validate_plan(domain, no_metric, {"(drive a c)"});
    EXPECT_TRUE(unit.valid) << unit.error;
    EXPECT_EQ(unit.cost, 1);
}

} // namespace
} // namespace envdesign::validate
