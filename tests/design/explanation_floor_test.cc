// The explanation floor (explanation_floor.h): the fewest differences that stop one cheaper
// human plan, against trying every subset of every difference, and never above the minimal
// explanation, on the seeded tasks of explaining_generator.h and the paper's Blocksworld.

#include "design/reconciliation/explanation_floor.h"
#include "design/reconciliation/minimal_explanation.h"
#include "explaining_generator.h"
#include "generated_models.h"
#include "pddl/parser.h"
#include "pddl/sexpr.h"
#include "validate/plan_validator.h"

#include <gtest/gtest.h>

namespace envdesign::design {
namespace {

using testing::generate_pair;
using testing::GeneratedPair;
using testing::models_of;

// The least size of a subset of every difference (relevant or not) after which `plan` is no
// longer valid at a human cost below `below`, trying all 2^n; -1 if none does that.
int least_stopping_subset(const ModelPair &m, const std::vector<ModelDifference> &all,
                          const std::vector<std::string> &plan, double below) {
    return testing::smallest_passing_subset(
        static_cast<int>(all.size()), [&](const std::vector<int> &chosen) {
            ModelPair told = told_models(m, all, chosen);
            auto v = validate::validate_plan(told.human_domain, told.human_problem, plan);
            return !v.valid || static_cast<double>(v.cost) >= below;
        });
}

// pi_R's human cost once every difference is told (P_H then has P_R's schemas, initial state
// and goal, with the human's costs): what an explained pi_R costs people.
double explained_cost(const ModelPair &m, const std::vector<ModelDifference> &all,
                      const std::vector<std::string> &robot_plan) {
    std::vector<int> every(all.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        every[i] = static_cast<int>(i);
    ModelPair told = told_models(m, all, every);
    auto v = validate::validate_plan(told.human_domain, told.human_problem, robot_plan);
    return v.valid ? static_cast<double>(v.cost) : INF;
}

TEST(ExplanationFloor, EqualsEverySubsetAndNeverExceedsTheExplanation) {
    int compared = 0, two_or_more = 0, below_explanation = 0;
    for (unsigned seed = 0; seed < 300; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        GeneratedPair g = generate_pair(seed);
        ModelPair m = models_of(g);
        PlanCache planner(planning::PlannerOptions{});
        PlanOutcome robot =
            solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
        PlanOutcome human = solve_model(m.human_domain, m.human_problem, planner, Deadline{});
        if (robot.status != PlanStatus::SOLVED || human.status != PlanStatus::SOLVED)
            continue;
        std::vector<ModelDifference> all = model_differences(m, false);
        double below = explained_cost(m, all, robot.plan);
        if (!(static_cast<double>(human.cost) < below))
            continue; // the human's plan is no cheaper: nothing to stop
        int floor = explanation_floor(m, human.plan, below, 1 << 20);
        int expected = least_stopping_subset(m, all, human.plan, below);
        if (expected < 0) // nothing stops it: the floor says more than any subset holds
            EXPECT_GT(floor, static_cast<int>(model_differences(m).size()));
        else
            EXPECT_EQ(floor, expected);
        ExplanationSearch search = minimal_explanation(m, robot.plan, planner, Deadline{});
        ASSERT_NE(search.status, ExplanationStatus::LIMIT);
        if (search.status == ExplanationStatus::FOUND) {
            EXPECT_LE(floor, static_cast<int>(search.chosen.size()));
            below_explanation += floor < static_cast<int>(search.chosen.size());
        }
        // A budget of one subset answers what it proved: the sizes below the first.
        int budget = explanation_floor(m, human.plan, below, 1);
        EXPECT_GE(budget, 1);
        EXPECT_LE(budget, floor);
        ++compared;
        two_or_more += floor >= 2;
    }
    std::cout << "compared " << compared << ", floors >= 2: " << two_or_more
              << ", below the minimal explanation: " << below_explanation << "\n";
    EXPECT_GE(compared, 60);
    EXPECT_GE(two_or_more, 3); // the coupled pair ((ready) precondition and delete) is met
}

// The paper's Blocksworld 20, no design: people think the hand holds several blocks, and the
// robot's plan needs the four (handempty) differences told. The human's optimal plan alone
// is stopped by two: a precondition with its delete (a pick-up or unstack that empties the
// hand), so the floor is 2, below the explanation's 4, and 0 when pi_R is no dearer.
TEST(ExplanationFloor, PaperBlocksworldNeedsTheCoupledPair) {
    ModelPair m = testing::paper_blocksworld("20/init-7-1-goal-7-0.pddl");
    PlanCache planner(planning::PlannerOptions{});
    PlanOutcome robot =
        solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
    PlanOutcome human = solve_model(m.human_domain, m.human_problem, planner, Deadline{});
    ASSERT_EQ(robot.cost, 22);
    ASSERT_EQ(human.cost, 14);
    EXPECT_EQ(explanation_floor(m, human.plan, 22), 2);
    EXPECT_EQ(explanation_floor(m, human.plan, 14), 0);
    ExplanationSearch search = minimal_explanation(m, robot.plan, planner, Deadline{});
    ASSERT_EQ(search.status, ExplanationStatus::FOUND);
    EXPECT_EQ(search.chosen.size(), 4u);
}

} // namespace
} // namespace envdesign::design
