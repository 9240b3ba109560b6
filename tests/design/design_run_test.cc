// One design run (design/design_run.h): the settings resolved against the spec's, the
// explanation of the answer (and when it is left out), and the warnings every entry point
// now gets from the run itself.

#include "design/design_run.h"
#include "design/evaluation/local_evaluator.h"
#include "example_paths.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <atomic>

namespace envdesign::design {
namespace {

const std::string RUN_RESTAURANT_C = RESTAURANT + "c-two-tasks-t10.textproto";

TEST(DesignRun, SettingsTakeTheSpecsWhereTheCallerSaysNothing) {
    DesignProblem problem = spec::load_design_problem(RUN_RESTAURANT_C);
    problem.max_design_size = 2;
    problem.time_limit_s = 30;
    DesignSearchOptions spec_s = search_options(problem, {});
    EXPECT_EQ(spec_s.max_design_size, 2);
    ASSERT_TRUE(spec_s.deadline.limited());
    EXPECT_GT(spec_s.deadline.remaining_seconds(), 29);
    EXPECT_LE(spec_s.deadline.remaining_seconds(), 30);

    RunSettings settings;
    settings.max_design_size = 0; // every size
    settings.time_limit_s = 0;    // none
    settings.ranking = 3;
    settings.batch_size = 0; // at least one configuration a batch
    DesignSearchOptions mine = search_options(problem, settings);
    EXPECT_EQ(mine.max_design_size, 0);
    EXPECT_FALSE(mine.deadline.limited());
    EXPECT_EQ(mine.ranking, 3);
    EXPECT_EQ(mine.batch_size, 1);

    // The coordinator's cap: "no limit" and anything longer become the cap.
    settings.max_time_limit_s = 100;
    EXPECT_NEAR(search_options(problem, settings).deadline.remaining_seconds(), 100, 1);
    settings.time_limit_s = 1e4;
    EXPECT_NEAR(search_options(problem, settings).deadline.remaining_seconds(), 100, 1);
    settings.time_limit_s = 5;
    EXPECT_NEAR(search_options(problem, settings).deadline.remaining_seconds(), 5, 1);
}

// The restaurant (c): the run's answer is the search's, explained ({00-01, 10-11}, 85.2632,
// design_explanation_test.cc works it out), and the spec's warnings come first.
TEST(DesignRun, TheAnswerIsExplainedAndTheSpecsWarningsTravel) {
    DesignProblem problem = spec::load_design_problem(RUN_RESTAURANT_C);
    problem.warnings = {"spec:1:1: warning: a made-up warning"};
    LocalEvaluator local(problem, 1);
    EvaluationLog log(problem, local);
    DesignRun run = run_design(problem, log, &local.planner(), {});
    ASSERT_TRUE(run.result.best);
    EXPECT_TRUE(run.result.optimal);
    EXPECT_NEAR(run.result.best->objective.value, 85.2632, 1e-4);
    ASSERT_TRUE(run.explanation);
    EXPECT_EQ(run.explanation->chosen.configuration, run.result.best->ranked.configuration);
    EXPECT_EQ(run.explanation->marginal.size(), 2u);
    EXPECT_EQ(run.warnings, problem.warnings);
}

// A run stopped before it starts (Ctrl-C, a cancelled request) still answers with what it
// has; it is explained only where the caller wants it (the CLI), not for a cancelled request.
TEST(DesignRun, AStoppedRunIsExplainedOnlyWhenTheCallerWantsIt) {
    DesignProblem problem = spec::load_design_problem(RUN_RESTAURANT_C);
    std::atomic<bool> stop{true};
    for (bool explain_when_stopped : {true, false}) {
        LocalEvaluator local(problem, 1);
        EvaluationLog log(problem, local);
        RunSettings settings;
        settings.stop = &stop;
        settings.explain_when_stopped = explain_when_stopped;
        DesignRun run = run_design(problem, log, &local.planner(), settings);
        EXPECT_TRUE(run.result.limit_reached);
        EXPECT_FALSE(run.result.optimal);
        EXPECT_EQ(run.explanation.has_value(), explain_when_stopped && run.result.best);
    }
}

// Each task no design can make explicable is named with its reason, in task order, after
// the spec's warnings; without a planner (store-only re-weighing) nothing is planned.
TEST(DesignRun, TasksNoDesignCanMakeExplicableAreNamedWithTheReason) {
    DesignProblem problem = spec::load_design_problem(std::string(ENVDESIGN_TEST_DATA) +
                                                      "/usability/unsolvable-tasks.textproto");
    LocalEvaluator local(problem, 1);
    EvaluationLog log(problem, local);
    DesignRun run = run_design(problem, log, &local.planner(), {});
    const std::string lead = "has infinite IE in the unmodified models: ";
    std::vector<std::string> want = problem.warnings;
    want.push_back("task 'robot-stuck' " + lead + "P_R has no plan (the robot cannot do the task)");
    want.push_back("task 'human-stuck' " + lead +
                   "P_H has no plan (observers believe the task impossible)");
    want.push_back("task 'disagree' " + lead +
                   "no plan is valid in both P_R and P_H (P_mod has no plan)");
    EXPECT_EQ(run.warnings, want);

    LocalEvaluator again(problem, 1);
    EvaluationLog log_again(problem, again);
    DesignRun unplanned = run_design(problem, log_again, nullptr, {});
    EXPECT_EQ(unplanned.warnings, problem.warnings);
    ASSERT_TRUE(unplanned.explanation);
    EXPECT_FALSE(unplanned.explanation->tasks.at(3).robot_plan); // no planner: no plan shown
}

} // namespace
} // namespace envdesign::design
