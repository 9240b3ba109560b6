// gated_twin_restricting on the paper's Blocksworld from-table-x modifications, and on the
// changes that each break one condition of gated_twins.h.

#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "design/search/gated_twins.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

namespace envdesign::design {
namespace {

const std::string PAPER_20 =
    std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/20/design-t1.textproto";

DesignProblem paper() { return spec::load_design_problem(PAPER_20); }

pddl::Atom atom(const std::string &predicate, const std::string &arg) {
    pddl::Atom a;
    a.predicate = predicate;
    a.args = {arg};
    return a;
}

pddl::Action &action_named(pddl::Domain &domain, const std::string &name) {
    for (auto &a : domain.actions)
        if (a.name == name)
            return a;
    throw std::runtime_error("no action " + name);
}

TEST(GatedTwins, FromTableGatesTheRobotAndTheHuman) {
    DesignProblem problem = paper();
    ASSERT_EQ(problem.modifications.size(), 7u);
    for (int m = 0; m < 7; ++m) {
        EXPECT_TRUE(gated_twin_restricting(problem, m, true)) << m;
        EXPECT_TRUE(gated_twin_restricting(problem, m, false)) << m;
    }
}

TEST(GatedTwins, AGateATaskAlreadyHoldsIsNotAGate) {
    DesignProblem problem = paper();
    problem.tasks[1].robot_problem.init.push_back(atom("restricted", "a"));
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
    EXPECT_TRUE(gated_twin_restricting(problem, 0, false)); // the human's task is unchanged
}

TEST(GatedTwins, ATwinWithOtherEffectsIsNoTwin) {
    DesignProblem problem = paper();
    action_named(problem.robot_domain, "stack-from-table")
        .effect.push_back(pddl::Literal{atom("ontable", "?y"), false});
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
}

TEST(GatedTwins, ATwinThatDropsABasePreconditionIsNoTwin) {
    DesignProblem problem = paper();
    auto &pre = action_named(problem.robot_domain, "stack-from-table").precondition;
    pre.erase(pre.begin()); // (holding ?x)
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
}

TEST(GatedTwins, AFluentReadByAnotherSchemaBreaksTheRule) {
    DesignProblem problem = paper();
    action_named(problem.robot_domain, "put-down")
        .precondition.push_back(pddl::Literal{atom("from-table", "?x"), true});
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
}

TEST(GatedTwins, FamilyMembersMustEditTheFluentsAlike) {
    DesignProblem problem = paper();
    problem.modifications[3].edits.pop_back(); // from-table-d no longer clears on unstack
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
    EXPECT_FALSE(gated_twin_restricting(problem, 3, true));
}

TEST(GatedTwins, AModificationThatEditsATwinIsNoGate) {
    DesignProblem problem = paper();
    Edit edit = problem.modifications[2].edits[1];
    edit.action = "stack";
    problem.modifications[2].edits.push_back(edit);
    EXPECT_FALSE(gated_twin_restricting(problem, 0, true));
}

// The claim itself, on the paper's smaller Blocksworld problems: adding a gate never lowers
// c_R*, from any configuration, in any task (the planner, not the rule, decides).
TEST(GatedTwins, TheRobotsOptimalCostNeverDropsWhenAGateIsAdded) {
    int pairs = 0, rises = 0;
    for (const char *number : {"01", "06", "11"}) {
        DesignProblem problem =
            spec::load_design_problem(std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/" +
                                      number + "/design-t1.textproto");
        LocalEvaluator evaluator(problem, 1);
        int n = static_cast<int>(problem.modifications.size());
        for (int m = 0; m < n; ++m)
            ASSERT_TRUE(gated_twin_restricting(problem, m, true)) << number << " " << m;
        for (unsigned set = 0; set < (1u << n); ++set) {
            Configuration c;
            for (int m = 0; m < n; ++m)
                if (set & (1u << m))
                    c.push_back(m);
            for (int m = 0; m < n; ++m) {
                if (set & (1u << m))
                    continue;
                Configuration larger = c;
                larger.insert(std::upper_bound(larger.begin(), larger.end(), m), m);
                for (int t = 0; t < static_cast<int>(problem.tasks.size()); ++t) {
                    auto before = evaluator.robot_cost_bound(c, t, {});
                    auto after = evaluator.robot_cost_bound(larger, t, {});
                    ASSERT_TRUE(before && after);
                    EXPECT_GE(*after, *before) << number << " " << m << " task " << t;
                    ++pairs;
                    rises += *after > *before;
                }
            }
        }
    }
    EXPECT_GT(rises, 0) << pairs; // a gate can cost the robot: the test can see a drop
}

} // namespace
} // namespace envdesign::design
