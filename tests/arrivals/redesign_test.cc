// Re-evaluation for a new D: the same designs as fresh searches, by re-weighting stored
// evaluations (no planner runs once they are stored), new tasks added or refused.

#include "arrivals/redesign.h"
#include "restaurant_drift.h"

#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace envdesign::arrivals {
namespace {

const std::string DATA = ENVDESIGN_ARRIVALS_DATA;
const std::string RESTAURANT = DATA + "/../../../examples/restaurant/";

std::string read(const std::string &path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> names(const Redesigner &r, const design::DesignResult &result) {
    return design::design_names(r.problem(), result.best->ranked.configuration);
}

TEST(Redesign, FirstRunIsTheSpecsDesign) {
    Redesigner r(spec::load_design_problem(RESTAURANT_DRIFT), {});
    Redesign first = r.redesign(r.distribution(), {});
    ASSERT_TRUE(first.result.best);
    EXPECT_TRUE(first.result.optimal);
    EXPECT_EQ(names(r, first.result), std::vector<std::string>{});
    EXPECT_NEAR(first.result.best->objective.value, 38.143006484, 1e-6);
    EXPECT_FALSE(first.change.changed);
    EXPECT_TRUE(std::isnan(first.change.objective_before));
    EXPECT_GT(first.change.planner_runs, 0);
    // The run explains its answer as the CLI's and the coordinator's do (design_run.h).
    ASSERT_TRUE(first.explanation);
    EXPECT_EQ(first.explanation->chosen.configuration, first.result.best->ranked.configuration);
    EXPECT_EQ(first.explanation->tasks.size(), r.problem().tasks.size());
}

// A bridge restarted on the same state directory (--state-dir) re-weights what its
// predecessor evaluated: a drift after the restart costs no planner run.
TEST(Redesign, ARestartedRedesignerFindsItsEvaluationsInTheStateFile) {
    auto dir = std::filesystem::temp_directory_path() /
               ("envdesign-redesign-state-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    auto open = [&] {
        store::RecordDbOptions options;
        options.sync = false;
        return std::make_shared<store::RecordDb>((dir / "evaluations.db").string(), options);
    };
    RedesignOptions options;
    options.evaluations = open();
    {
        Redesigner before(spec::load_design_problem(RESTAURANT_DRIFT), options);
        EXPECT_GT(before.redesign(g1(0.9), {}).change.planner_runs, 0);
        EXPECT_GT(before.redesign(g1(0.1), {}).change.planner_runs, 0);
    }
    options.evaluations = open(); // the process restarted
    Redesigner after(spec::load_design_problem(RESTAURANT_DRIFT), options);
    Redesign again = after.redesign(g1(0.1), {});
    EXPECT_EQ(again.change.planner_runs, 0);
    EXPECT_EQ(names(after, again.result), names(after, fresh(g1(0.1))));
    std::filesystem::remove_all(dir);
}

// 0.9 -> 0.1 flips the design to barrier-00-01, as a fresh search says; the old design
// costs more under the new D. Going back and forth again costs no planner run.
TEST(Redesign, DriftFlipsTheDesignThenReweightingIsFree) {
    Redesigner r(spec::load_design_problem(RESTAURANT_DRIFT), {});
    r.redesign(g1(0.9), {});
    Redesign flip = r.redesign(g1(0.1), {});
    EXPECT_TRUE(flip.change.changed);
    EXPECT_EQ(flip.change.after_names, std::vector<std::string>{"barrier-00-01"});
    EXPECT_EQ(flip.change.before_names, std::vector<std::string>{});
    EXPECT_NEAR(flip.change.distance, 0.8, 1e-12);
    EXPECT_GT(flip.change.objective_before, flip.change.objective_after);
    EXPECT_NE(flip.change.explanation.find("{} -> {barrier-00-01}"), std::string::npos)
        << flip.change.explanation;
    design::DesignResult expected = fresh(g1(0.1));
    EXPECT_EQ(flip.result.best->ranked.configuration, expected.best->ranked.configuration);
    EXPECT_NEAR(flip.result.best->objective.value, expected.best->objective.value, 1e-9);

    for (double p : {0.9, 0.1, 0.9, 0.1}) {
        Redesign again = r.redesign(g1(p), {});
        EXPECT_EQ(again.change.planner_runs, 0) << p;
        EXPECT_EQ(again.result.counters.evaluator.task_evaluations, 0) << p;
        // Every configuration the search looked at, probes included, came from the store.
        const auto &c = again.result.counters;
        EXPECT_EQ(again.change.stored_answers,
                  c.configurations_evaluated + c.configurations_abandoned + c.configurations_probed)
            << p;
        EXPECT_TRUE(again.change.changed) << p;
    }
}

// Re-weighting is exact: for D along the way, the design and objective of a fresh search.
TEST(Redesign, SameAsFreshSearchesAlongTheDrift) {
    Redesigner r(spec::load_design_problem(RESTAURANT_DRIFT), {});
    for (double p : {0.9, 0.8, 0.75, 0.7, 0.5, 0.3, 0.1, 0.0, 1.0, 0.85}) {
        Redesign got = r.redesign(g1(p), {});
        design::DesignResult expected = fresh(g1(p));
        ASSERT_TRUE(got.result.best && expected.best);
        EXPECT_EQ(got.result.best->ranked.configuration, expected.best->ranked.configuration) << p;
        EXPECT_NEAR(got.result.best->objective.value, expected.best->objective.value, 1e-9) << p;
        EXPECT_EQ(got.result.optimal, expected.optimal) << p;
    }
}

// A new task with its problem: added, evaluated, weighed. Here a third booth task that is
// serve-g2 again under another name, so the answer is known: with D = 0.9 on it the design
// is the one for serve-g2-heavy D.
TEST(Redesign, NewTaskIsAddedAndEvaluated) {
    Redesigner r(spec::load_design_problem(RESTAURANT_DRIFT), {});
    r.redesign(r.distribution(), {});
    NewTask task{"serve-g2-again", read(RESTAURANT + "serve-g2.pddl"),
                 read(RESTAURANT + "serve-g2-human.pddl")};
    Redesign got =
        r.redesign({{"serve-g1", 0.1}, {"serve-g2", 0.0}, {"serve-g2-again", 0.9}}, {task});
    EXPECT_EQ(got.change.added_tasks, std::vector<std::string>{"serve-g2-again"});
    EXPECT_TRUE(got.change.refused_tasks.empty());
    ASSERT_EQ(r.problem().tasks.size(), 3u);
    EXPECT_EQ(got.change.after_names, std::vector<std::string>{"barrier-00-01"});
    design::DesignResult expected = fresh(g1(0.1));
    EXPECT_NEAR(got.result.best->objective.value, expected.best->objective.value, 1e-9);
    // The new task was weighed with its own evaluation; its models equal serve-g2's, so the
    // content-addressed store (or plan cache) answers for it, with serve-g2's values.
    const auto &tasks = got.result.best->tasks;
    ASSERT_EQ(tasks.size(), 3u);
    EXPECT_EQ(tasks[2].ie, tasks[1].ie);
    EXPECT_EQ(tasks[2].robot_cost, tasks[1].robot_cost);
    EXPECT_EQ(tasks[2].plan, tasks[1].plan);
}

// Bad PDDL for a new task: refused with the parser's message; the search still runs.
TEST(Redesign, BadNewTaskIsRefused) {
    Redesigner r(spec::load_design_problem(RESTAURANT_DRIFT), {});
    r.redesign(r.distribution(), {});
    Redesign got = r.redesign(g1(0.1), {{"broken", "(define (problem x) (:domain restaurant)", ""},
                                        {"ghost",
                                         "(define (problem y) (:domain restaurant) "
                                         "(:objects nowhere - cell) (:init) "
                                         "(:goal (robot-at nowhere)))",
                                         ""}});
    EXPECT_EQ(got.change.refused_tasks.size(), 2u);
    EXPECT_EQ(r.problem().tasks.size(), 2u);
    ASSERT_TRUE(got.result.best);
    EXPECT_EQ(got.change.after_names, std::vector<std::string>{"barrier-00-01"});
}

} // namespace
} // namespace envdesign::arrivals
