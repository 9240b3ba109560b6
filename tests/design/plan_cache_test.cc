// The plan cache's two choices of plan (plan_cache.h): ANY_OPTIMAL is the A* with inherited
// LM-cut, PLANNERS the planner's own A*; each choice answers with its own search's plan, in
// whichever order they are asked, by ground task and by lifted model, and both have the
// optimal cost.

#include "design/behaviour/explicability.h"
#include "design/evaluation/plan_cache.h"
#include "design/model/ground_key.h"
#include "ground/grounder.h"
#include "pddl/parser.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace envdesign::design {
namespace {

const std::string DRIVERLOG = std::string(ENVDESIGN_TEST_DATA) + "/paper/driverlog/";

planning::PlanReport plan_canonical(const ground::GroundTask &task, bool inherit_cuts) {
    planning::PlannerOptions options;
    options.inherit_cuts = inherit_cuts;
    return planning::plan_task(canonicalize(task), options);
}

TEST(PlanCache, EachChoiceOfPlanIsItsOwnSearchsWhicheverIsAskedFirst) {
    // Driverlog has several optimal plans per task, and the two searches part on some.
    pddl::Domain domain = pddl::parse_domain_file(DRIVERLOG + "domain-robot.pddl");
    int tasks = 0, plans_differ = 0;
    for (const char *folder : {"03", "05", "08"}) {
        for (const auto &entry : std::filesystem::directory_iterator(DRIVERLOG + folder)) {
            if (entry.path().extension() != ".pddl")
                continue;
            SCOPED_TRACE(entry.path().string());
            pddl::Problem problem = pddl::parse_problem_file(entry.path().string(), domain);
            ground::GroundTask task = ground::ground(domain, problem);
            planning::PlanReport planners = plan_canonical(task, false);
            planning::PlanReport inherited = plan_canonical(task, true);
            ASSERT_EQ(planners.status, search::SearchStatus::SOLVED);
            ASSERT_EQ(inherited.cost, planners.cost);
            plans_differ += inherited.plan != planners.plan;
            PlanCache cache(planning::PlannerOptions{});
            const bool planners_first = tasks++ % 2 == 0;
            PlanChoice first = planners_first ? PlanChoice::PLANNERS : PlanChoice::ANY_OPTIMAL;
            PlanChoice second = planners_first ? PlanChoice::ANY_OPTIMAL : PlanChoice::PLANNERS;
            PlanOutcome a = cache.solve(task, Deadline{}, first);
            PlanOutcome b = cache.solve(task, Deadline{}, second);
            PlanOutcome again = cache.solve(task, Deadline{}, first);
            const PlanOutcome &p = planners_first ? a : b, &any = planners_first ? b : a;
            EXPECT_EQ(p.plan, planners.plan);
            EXPECT_EQ(any.plan, inherited.plan);
            EXPECT_EQ(p.cost, planners.cost);
            EXPECT_EQ(any.cost, planners.cost);
            EXPECT_EQ(again.plan, a.plan);
            EXPECT_EQ(cache.counters().planner_runs, 2);
            EXPECT_EQ(cache.counters().cache_hits, 1);
            // The same through the lifted models, as the evaluations ask.
            PlanCache by_model(planning::PlannerOptions{});
            PlanOutcome m1 = solve_model(domain, problem, by_model, Deadline{}, first);
            PlanOutcome m2 = solve_model(domain, problem, by_model, Deadline{}, second);
            EXPECT_EQ((planners_first ? m1 : m2).plan, planners.plan);
            EXPECT_EQ((planners_first ? m2 : m1).plan, inherited.plan);
        }
    }
    EXPECT_GT(tasks, 8);
    EXPECT_GT(plans_differ, 0); // else the test could not tell the choices apart
}

} // namespace
} // namespace envdesign::design
