// Cases a code review found mishandled: equality in goals, a human model whose domain has
// another name than the robot's, and pathologically nested input.

#include "run_command.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace envdesign::testing {
namespace {

const std::string DIR = std::string(ENVDESIGN_TEST_DATA) + "/review/";

TEST(ReviewFindings, EqualityInTheGoalIsEvaluated) {
    CommandResult r =
        run_envdesign("plan " + DIR + "robot-domain.pddl " + DIR + "goal-equal.pddl", false);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out, "(move a b)\n; cost = 1 (unit cost)\n");
    r = run_envdesign("plan " + DIR + "robot-domain.pddl " + DIR + "goal-not-equal.pddl", false);
    EXPECT_EQ(r.exit_code, 3);
}

TEST(ReviewFindings, TheRobotsProblemServesAHumanDomainOfAnotherName) {
    CommandResult r = run_envdesign("explicable --json --robot-domain " + DIR +
                                        "robot-domain.pddl --human-domain " + DIR +
                                        "human-domain.pddl --problem " + DIR + "problem.pddl",
                                    false);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("\"robot_cost\":1"), std::string::npos) << r.out;
}

TEST(ReviewFindings, DeepNestingIsBadInputNotACrash) {
    std::string path = ::testing::TempDir() + "/deep.pddl";
    {
        std::ofstream out(path);
        out << std::string(200000, '(') << std::string(200000, ')');
    }
    CommandResult r = run_envdesign("plan " + path + " " + path);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(":1:10001: error: parentheses nested more than 10000 deep"),
              std::string::npos)
        << r.out.substr(0, 300);
    std::remove(path.c_str());
}

} // namespace
} // namespace envdesign::testing
