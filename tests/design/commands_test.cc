// `envdesign explicable` and `envdesign design` as users run them: output, JSON, exit codes.

#include "../cli/run_command.h"
#include "example_paths.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace envdesign::testing {
namespace {

nlohmann::json run_json(const std::string &arguments, int expected_exit) {
    CommandResult result = run_envdesign(arguments, false);
    EXPECT_EQ(result.exit_code, expected_exit) << result.out;
    return nlohmann::json::parse(result.out);
}

// Serving G2 the robot needs 8 actions, the customers expect 4: IE = e^4.
TEST(ExplicableCommand, JsonOfTheRestaurant) {
    auto out =
        run_json("explicable --robot-domain " + RESTAURANT + "domain.pddl --problem " + RESTAURANT +
                     "serve-g2.pddl --human-problem " + RESTAURANT + "serve-g2-human.pddl --json",
                 0);
    EXPECT_EQ(out["status"], "solved");
    EXPECT_NEAR(out["ie"].get<double>(), std::exp(4.0), 1e-9);
    EXPECT_EQ(out["robot_cost"], 8);
    EXPECT_EQ(out["human_plan_cost"], 8);
    EXPECT_EQ(out["human_optimal_cost"], 4);
    EXPECT_EQ(out["plan"].size(), 8u);
    EXPECT_EQ(out["plan"][0], "(pick-up dish c00)");
}

TEST(ExplicableCommand, NoCommonPlanIsInfiniteAndExitsThree) {
    auto out = run_json("explicable --robot-domain " + ROADS + "domain.pddl --problem " + ROADS +
                            "robot.pddl --human-problem " + ROADS + "robot-only.pddl --json",
                        3);
    EXPECT_EQ(out["status"], "unsolvable");
    EXPECT_EQ(out["ie"], "inf");
    EXPECT_EQ(out["robot_cost"], "inf");
    EXPECT_EQ(out["human_optimal_cost"], 1);
}

TEST(ExplicableCommand, CostDiffDistance) {
    auto out = run_json("explicable --robot-domain " + ROADS + "domain.pddl --problem " + ROADS +
                            "robot.pddl --human-problem " + ROADS +
                            "human.pddl --distance COST_DIFF --json",
                        0);
    EXPECT_EQ(out["ie"], 3);
    EXPECT_EQ(out["robot_cost"], 2);
}

TEST(DesignCommand, JsonOfSettingC) {
    auto out = run_json("design " + RESTAURANT + "c-two-tasks-t10.textproto --json --workers 2", 0);
    EXPECT_EQ(out["status"], "optimal");
    EXPECT_EQ(out["design"], nlohmann::json({"barrier-00-01", "barrier-10-11"}));
    double objective = out["objective"];
    const auto &terms = out["terms"];
    // objective = alpha * inexplicability + beta * design_cost + kappa * robot_cost
    EXPECT_NEAR(objective,
                1 * terms["inexplicability"].get<double>() +
                    30 * terms["design_cost"].get<double>() +
                    0.25 * terms["robot_cost"].get<double>(),
                1e-9);
    EXPECT_NEAR(objective, 85.263215599, 1e-6);
    EXPECT_EQ(out["tasks"].size(), 2u);
    EXPECT_EQ(out["tasks"][1]["name"], "serve-g2");
    EXPECT_EQ(out["tasks"][1]["ie"], 1);
    EXPECT_TRUE(out["baseline"]["objective"].is_number());
    EXPECT_GT(out["configurations_evaluated"].get<int>(), 0);
    EXPECT_GT(out["planner_runs"].get<int>(), 0);
    EXPECT_TRUE(out["seconds"].is_number());
}

TEST(DesignCommand, MaxDesignSizeFromTheCommandLine) {
    auto out = run_json(
        "design " + RESTAURANT + "c-two-tasks-t10.textproto --json --max-design-size 1", 0);
    EXPECT_EQ(out["design"], nlohmann::json::array({"barrier-00-01"}));
    auto every = run_json("design " + RESTAURANT +
                              "c-two-tasks-t10.textproto --json --max-design-size 1 "
                              "--search exhaustive",
                          0);
    EXPECT_EQ(every["configurations_total"], 7); // {} and the 6 single modifications
    EXPECT_EQ(every["design"], out["design"]);
    EXPECT_EQ(every["objective"], out["objective"]);
}

TEST(DesignCommand, ATimeLimitThatStopsTheSearchExitsFour) {
    auto out = run_json(
        "design " + RESTAURANT + "c-two-tasks-t10.textproto --json --time-limit 0.000001", 4);
    EXPECT_EQ(out["status"], "best_found");
    EXPECT_TRUE(out["limit_reached"].get<bool>());
}

TEST(DesignCommand, PruneRelevantIsNotProvenOptimal) {
    auto out =
        run_json("design " + RESTAURANT + "c-two-tasks-t10.textproto --json --prune relevant", 0);
    EXPECT_EQ(out["status"], "best_found");
    EXPECT_GT(out["configurations_pruned"].get<int>(), 0);
}

TEST(DesignCommand, OneSummaryLineOnStderrWhenNotATerminal) {
    // stderr onto the pipe, stdout away: what a log file of a batch run would get.
    CommandResult result =
        run_envdesign("design " + RESTAURANT +
                          "a-one-task-t1.textproto --search exhaustive 3>&1 1>/dev/null 2>&3 | cat",
                      false);
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.out.rfind("design: the search considered 64 configurations: 1 evaluated in "
                               "full, 0 abandoned and 63 skipped by the bound",
                               0),
              0u)
        << result.out;
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 1) << result.out;
}

// Setting (c)'s three best (tests/design/restaurant_test.cc works them out by hand): the two
// pairs that close every shortcut (f_10 + 60 + 18.75), then one barrier on G2's shortcut
// (f_10 e^2 + 30 + 18.75), the same from both searches.
TEST(DesignCommand, RankingOfSettingC) {
    const double f = 6.513215599;
    for (std::string search : {"witness", "exhaustive"}) {
        auto out = run_json("design " + RESTAURANT +
                                "c-two-tasks-t10.textproto --json --ranking 3 --search " + search,
                            0);
        EXPECT_EQ(out["status"], "optimal");
        ASSERT_EQ(out["ranking"].size(), 3u) << search;
        EXPECT_EQ(out["ranking"][0]["design"], out["design"]);
        EXPECT_EQ(out["ranking"][1]["design"], nlohmann::json({"barrier-01-02", "barrier-11-12"}));
        EXPECT_EQ(out["ranking"][2]["design"], nlohmann::json({"barrier-00-01"}));
        EXPECT_NEAR(out["ranking"][1]["objective"].get<double>(), f + 78.75, 1e-6);
        EXPECT_NEAR(out["ranking"][2]["objective"].get<double>(), f * std::exp(2.0) + 48.75, 1e-6);
    }
    // Without --ranking there is no "ranking"; a negative N is refused. (With --connect the
    // request carries N: tests/e2e, EndToEnd.CliConnectRanksAsTheLocalRun.)
    auto plain = run_json("design " + RESTAURANT + "c-two-tasks-t10.textproto --json", 0);
    EXPECT_FALSE(plain.contains("ranking"));
    CommandResult negative =
        run_envdesign("design " + RESTAURANT + "c-two-tasks-t10.textproto --ranking -1");
    EXPECT_EQ(negative.exit_code, 2) << negative.out;
    EXPECT_NE(negative.out.find("--ranking"), std::string::npos) << negative.out;
}

} // namespace
} // namespace envdesign::testing
