// The Blocksworld design example (examples/blocksworld): schema edits on both models, a
// new predicate, and a modification that changes no ground task.

#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

const std::string BLOCKSWORLD = std::string(ENVDESIGN_EXAMPLES) + "/blocksworld/design.textproto";

int index_of(const DesignProblem &problem, const std::string &name) {
    for (std::size_t m = 0; m < problem.modifications.size(); ++m)
        if (problem.modifications[m].name == name)
            return static_cast<int>(m);
    return -1;
}

// Without design the observers expect the multi-block shortcuts: move-tower 6 (robot 10),
// swap-pairs 4 (robot 6), interleave 10 (robot 18). The sign makes all three IE 1.
TEST(Blocksworld, TheSignMakesEveryTaskExplicable) {
    DesignProblem problem = load_design_problem(BLOCKSWORLD);
    LocalEvaluator evaluator(problem, 2);
    DesignResult r = search_design(problem, evaluator, {});
    EXPECT_TRUE(r.optimal);
    EXPECT_EQ(design_names(problem, r.best->ranked.configuration),
              std::vector<std::string>{"one-hand-sign"});
    const double f = (1 - std::pow(0.9, 10)) / 0.1;
    const double robot = 10 * (0.4 * 10 + 0.4 * 6 + 0.2 * 18); // T * E[c_R] = 100
    EXPECT_NEAR(r.best->objective.value, f * 1 + 0.25 * 1.5 + 0.25 * robot, 1e-9);
    double baseline_ie = 0.4 * std::exp(4.0) + 0.4 * std::exp(2.0) + 0.2 * std::exp(8.0);
    EXPECT_NEAR(r.baseline->objective.value, f * baseline_ie + 0.25 * robot, 1e-6);
}

TEST(Blocksworld, EveryConfigurationWithoutBoundsAgrees) {
    DesignProblem problem = load_design_problem(BLOCKSWORLD);
    PlanCache planner(planning::PlannerOptions{});
    const double f = (1 - std::pow(0.9, 10)) / 0.1;
    RankedDesign best;
    int n = static_cast<int>(problem.modifications.size());
    for (int mask = 0; mask < (1 << n); ++mask) {
        Configuration c;
        double cost = 0;
        for (int m = 0; m < n; ++m)
            if (mask >> m & 1)
                c.push_back(m), cost += problem.modifications[m].cost;
        double ie = 0, robot = 0;
        for (int t = 0; t < 3; ++t) {
            auto e = evaluate_explicability(configured_models(problem, c, t),
                                            Distance::EXP_COST_DIFF, planner, Deadline{});
            ie += problem.tasks[t].probability * e.ie;
            robot += problem.tasks[t].probability * e.robot_cost;
        }
        RankedDesign candidate{f * ie + 0.25 * cost + 0.25 * 10 * robot, cost, c};
        if (mask == 0 || ranks_before(candidate, best))
            best = candidate;
    }
    LocalEvaluator evaluator(problem, 1);
    DesignResult r = search_design(problem, evaluator, {});
    EXPECT_EQ(r.best->ranked.configuration, best.configuration);
    EXPECT_NEAR(r.best->objective.value, best.objective, 1e-9);
}

TEST(Blocksworld, APosterNobodyReadsCostsNoPlannerRun) {
    DesignProblem problem = load_design_problem(BLOCKSWORLD);
    PlanCache planner(planning::PlannerOptions{});
    int poster = index_of(problem, "poster");
    ASSERT_GE(poster, 0);
    for (int t = 0; t < 3; ++t)
        evaluate_explicability(configured_models(problem, {}, t), Distance::EXP_COST_DIFF, planner,
                               Deadline{});
    long long runs = planner.counters().planner_runs;
    for (int t = 0; t < 3; ++t)
        evaluate_explicability(configured_models(problem, {poster}, t), Distance::EXP_COST_DIFF,
                               planner, Deadline{});
    EXPECT_EQ(planner.counters().planner_runs, runs);
    EXPECT_EQ(planner.counters().cache_hits, 6);
}

} // namespace
} // namespace envdesign::design
