// Minimal explanations (minimal_explanation.h) against trying every subset of the model
// differences, on seeded generated tasks (explaining_generator.h); the check itself against an
// enumeration of action sequences (brute_force.h, no planner); and hand-worked cases.

#include "brute_force.h"
#include "design/behaviour/explicability.h"
#include "design/reconciliation/minimal_explanation.h"
#include "example_paths.h"
#include "explaining_generator.h"
#include "generated_models.h"
#include "pddl/parser.h"
#include "pddl/sexpr.h"
#include "validate/plan_validator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

namespace envdesign::design {
namespace {

using testing::generate_pair;
using testing::GeneratedPair;
using testing::models_of;

// The smallest size of a subset of `all` that passes the check, by trying all 2^n of them
// (in order of the bit masks, not by size); -1 if none does.
int smallest_by_every_subset(const ModelPair &m, const std::vector<ModelDifference> &all,
                             const std::vector<std::string> &plan, PlanCache &planner) {
    return testing::smallest_passing_subset(
        static_cast<int>(all.size()), [&](const std::vector<int> &chosen) {
            return *plan_optimal_for_human(told_models(m, all, chosen), plan, planner, Deadline{});
        });
}

constexpr int SEEDS = 300;

// The issue's "Must show": the minimal explanation's size equals the smallest found by
// trying every subset of every difference (relevant or not: so the relevance pruning is
// checked too), on at least 100 seeded tasks where the robot has a plan.
TEST(MinimalExplanation, AgreesWithEverySubsetOnSeededTasks) {
    int compared = 0, nonempty = 0, two_or_more = 0, none = 0, pruned = 0, hitting = 0;
    for (unsigned seed = 0; seed < SEEDS; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        GeneratedPair g = generate_pair(seed);
        ModelPair m = models_of(g);
        PlanCache planner(planning::PlannerOptions{});
        PlanOutcome robot =
            solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
        if (robot.status != PlanStatus::SOLVED)
            continue;
        std::vector<ModelDifference> all = model_differences(m, false);
        ASSERT_LE(all.size(), 14u) << "the generator must keep 2^n small";
        int expected = smallest_by_every_subset(m, all, robot.plan, planner);
        ExplanationSearch search = minimal_explanation(m, robot.plan, planner, Deadline{});
        ASSERT_NE(search.status, ExplanationStatus::LIMIT);
        int found =
            search.status == ExplanationStatus::FOUND ? static_cast<int>(search.chosen.size()) : -1;
        EXPECT_EQ(found, expected);
        if (found >= 0) { // the explanation itself passes the check
            EXPECT_TRUE(*plan_optimal_for_human(told_models(m, search.differences, search.chosen),
                                                robot.plan, planner, {}));
        }
        ++compared;
        nonempty += found >= 1;
        two_or_more += found >= 2;
        none += found < 0;
        pruned += all.size() > search.differences.size();
        hitting += search.hitting_sets;
    }
    std::cout << "compared " << compared << ", explanations of size >= 1: " << nonempty
              << ", >= 2: " << two_or_more << ", none: " << none
              << ", irrelevant differences pruned in " << pruned << ", by hitting sets " << hitting
              << "\n";
    EXPECT_GE(compared, 250);
    EXPECT_GE(nonempty, 40);   // not trivial: most seeds need telling
    EXPECT_GE(two_or_more, 8); // and some need more than one difference
    EXPECT_GE(pruned, 20);     // and the pruning was exercised
    EXPECT_GE(hitting, 30);    // both methods (explanation_hitting.h and enumeration)
    EXPECT_GE(compared - hitting, 30);
}

// The first subset of `differences` that passes the check, by size and then in
// lexicographic order of indices (the enumeration's order); nullopt if none does.
std::optional<std::vector<int>> first_by_size(const ModelPair &m,
                                              const std::vector<ModelDifference> &differences,
                                              const std::vector<std::string> &plan,
                                              PlanCache &planner) {
    int n = static_cast<int>(differences.size());
    std::vector<std::vector<int>> subsets;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
        std::vector<int> chosen;
        for (int i = 0; i < n; ++i)
            if (mask & (1u << i))
                chosen.push_back(i);
        subsets.push_back(std::move(chosen));
    }
    std::sort(subsets.begin(), subsets.end(), [](const auto &a, const auto &b) {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    for (const auto &chosen : subsets)
        if (*plan_optimal_for_human(told_models(m, differences, chosen), plan, planner, {}))
            return chosen;
    return std::nullopt;
}

// The hitting-set search starts from the cheaper human plans earlier searches met
// (PlanCache::cheaper_plans), here those of the same task with the observers told one
// difference (as another design would tell them). Its explanation is the same as with nothing
// met before, and the same as the enumeration's (the lexicographically least of the least).
TEST(MinimalExplanation, HittingSetsDoNotDependOnPlansMetBefore) {
    int compared = 0, nonempty = 0, fewer_planner_calls = 0;
    for (unsigned seed = 0; seed < SEEDS; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ModelPair m = models_of(generate_pair(seed));
        PlanCache fresh(planning::PlannerOptions{}), shared(planning::PlannerOptions{});
        PlanOutcome robot =
            solve_model(m.robot_domain, m.robot_problem, fresh, Deadline{}, PlanChoice::PLANNERS);
        if (robot.status != PlanStatus::SOLVED)
            continue;
        ExplanationSearch alone = minimal_explanation(m, robot.plan, fresh, Deadline{});
        if (!alone.hitting_sets)
            continue;
        for (int d = 0; d < static_cast<int>(alone.differences.size()); ++d)
            minimal_explanation(told_models(m, alone.differences, {d}), robot.plan, shared, {});
        ExplanationSearch after = minimal_explanation(m, robot.plan, shared, Deadline{});
        ASSERT_EQ(after.status, alone.status);
        EXPECT_EQ(after.chosen, alone.chosen);
        std::optional<std::vector<int>> first =
            first_by_size(m, alone.differences, robot.plan, fresh);
        EXPECT_EQ(first.has_value(), alone.status == ExplanationStatus::FOUND);
        if (first) {
            EXPECT_EQ(*first, alone.chosen);
        }
        ++compared;
        nonempty += !alone.chosen.empty();
        fewer_planner_calls += after.planner_checks < alone.planner_checks;
    }
    std::cout << "compared " << compared << ", explanations of size >= 1: " << nonempty
              << ", fewer planner calls after other searches: " << fewer_planner_calls << "\n";
    EXPECT_GE(compared, 30);
    EXPECT_GE(nonempty, 15);
    EXPECT_GE(fewer_planner_calls, 5); // the plans met before were used
}

// The planner-based check against brute force: in P_H + E, pi_R's cost equals the least cost
// of any action sequence valid there (enumerated, checked by the plan validator).
TEST(MinimalExplanation, CheckAgreesWithEnumeratedHumanOptimum) {
    int checked = 0;
    for (unsigned seed = 0; seed < 60 && checked < 25; ++seed) {
        GeneratedPair g = generate_pair(seed);
        ModelPair m = models_of(g);
        PlanCache planner(planning::PlannerOptions{});
        PlanOutcome robot =
            solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
        if (robot.status != PlanStatus::SOLVED || robot.plan.size() > 4)
            continue;
        ExplanationSearch search = minimal_explanation(m, robot.plan, planner, Deadline{});
        if (search.status != ExplanationStatus::FOUND)
            continue;
        SCOPED_TRACE("seed " + std::to_string(seed));
        ModelPair told = told_models(m, search.differences, search.chosen);
        auto v = validate::validate_plan(told.human_domain, told.human_problem, robot.plan);
        ASSERT_TRUE(v.valid) << v.error;
        // Every action costs at least 1, so an optimal plan has at most c(pi_R) steps.
        auto brute = testing::brute_force_explicability(told, static_cast<int>(v.cost));
        EXPECT_EQ(brute.human_optimal_cost, static_cast<double>(v.cost));
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

ModelPair restaurant(const std::string &task) {
    ModelPair m;
    m.robot_domain = pddl::parse_domain_file(RESTAURANT + "domain.pddl");
    m.human_domain = m.robot_domain;
    m.robot_problem = pddl::parse_problem_file(RESTAURANT + task + ".pddl", m.robot_domain);
    m.human_problem = pddl::parse_problem_file(RESTAURANT + task + "-human.pddl", m.human_domain);
    return m;
}

std::vector<std::string> texts(const ExplanationSearch &s) {
    std::vector<std::string> out;
    for (int i : s.chosen)
        out.push_back(s.differences[i].text);
    return out;
}

// Restaurant, serve at G1 (c12) from c00: the observers believe in 6 two-way passages into
// the table cells c01, c11 that the robot lacks (12 init differences, all read by move). The
// robot goes round: c00 c10 c20 c21 c22 c12 (5 moves + pick + put = 7). The observers'
// shortest routes: c00 c01 c02 c12 or c00 c01 c11 c12 or c00 c10 c11 c12 (5 in all). Telling
// them c00-c01 is closed leaves c00 c10 c11 c12; telling also c10-c11 leaves only the round
// route (c21 c11 c12 needs c21 first: 6 moves, no cheaper). One difference is not enough
// (each of the two routes above survives one removal), so |E| = 2.
TEST(MinimalExplanation, RestaurantNeedsTwoClosedPassages) {
    ModelPair m = restaurant("serve-g1");
    PlanCache planner(planning::PlannerOptions{});
    PlanOutcome robot =
        solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
    ASSERT_EQ(robot.status, PlanStatus::SOLVED);
    EXPECT_EQ(robot.cost, 7);
    ExplanationSearch s = minimal_explanation(m, robot.plan, planner, Deadline{});
    ASSERT_EQ(s.status, ExplanationStatus::FOUND);
    EXPECT_EQ(s.differences.size(), 12u);
    EXPECT_EQ(texts(s),
              (std::vector<std::string>{"-init (connected c00 c01)", "-init (connected c10 c11)"}));
    // Every difference removes a passage people believe in (restricting): the hitting-set
    // search plans {} (a route through c01: its passages form the first set), then all of
    // them (the route c00 c10 c11 c12: the second set), then both sets (no cheaper route
    // left), then the least set hitting both, which is also the lexicographically least.
    EXPECT_TRUE(s.hitting_sets);
    EXPECT_EQ(s.subsets_tried, 4);
}

// The paper's Blocksworld problem 01 (tests/data/paper): the observers' pick-up and unstack
// neither need nor take the empty hand (4 differences, all restricting, but on the same
// predicate: a precondition and a delete of (handempty), so the hitting-set method does not
// apply). Task init-4-1 needs 10 robot steps where observers expect fewer: both the
// precondition and the delete of one schema at least must be told; every subset agrees.
TEST(MinimalExplanation, PaperBlocksworldAgreesWithEverySubset) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/";
    ModelPair m;
    m.robot_domain = pddl::parse_domain_file(dir + "domain-robot.pddl");
    m.human_domain = pddl::parse_domain_file(dir + "domain-human.pddl");
    int explained = 0;
    for (const char *task : {"init-4-0-goal-4-0", "init-4-1-goal-4-1", "init-4-2-goal-4-2"}) {
        SCOPED_TRACE(task);
        m.robot_problem = pddl::parse_problem_file(dir + "01/" + task + ".pddl", m.robot_domain);
        m.human_problem = pddl::parse_problem_file(dir + "01/" + task + ".pddl", m.human_domain);
        PlanCache planner(planning::PlannerOptions{});
        PlanOutcome robot =
            solve_model(m.robot_domain, m.robot_problem, planner, Deadline{}, PlanChoice::PLANNERS);
        ASSERT_EQ(robot.status, PlanStatus::SOLVED);
        std::vector<ModelDifference> all = model_differences(m, false);
        EXPECT_EQ(all.size(), 4u);
        ExplanationSearch s = minimal_explanation(m, robot.plan, planner, Deadline{});
        EXPECT_FALSE(s.hitting_sets);
        ASSERT_EQ(s.status, ExplanationStatus::FOUND);
        EXPECT_EQ(static_cast<int>(s.chosen.size()),
                  smallest_by_every_subset(m, all, robot.plan, planner));
        explained += !s.chosen.empty();
    }
    EXPECT_GE(explained, 1);
}

// Differences of every kind, named by position so that renamed parameters still match.
TEST(ModelDifferences, EveryKindAndParameterNamesByPosition) {
    ModelPair m;
    m.robot_domain = pddl::parse_domain(pddl::read_sexpr(R"((define (domain d)
        (:requirements :strips :negative-preconditions)
        (:predicates (p ?x) (q ?x) (r ?x) (s ?x))
        (:action a :parameters (?x) :precondition (and (p ?x) (not (s ?x)))
                   :effect (and (q ?x) (not (p ?x))))
        (:action b :parameters (?x) :precondition (q ?x) :effect (r ?x))))",
                                                         "r"),
                                        "r");
    m.human_domain = pddl::parse_domain(pddl::read_sexpr(R"((define (domain d)
        (:requirements :strips)
        (:predicates (p ?x) (q ?x) (r ?x) (s ?x))
        (:action a :parameters (?y) :precondition (p ?y) :effect (and (q ?y) (r ?y)))
        (:action c :parameters (?y) :precondition (p ?y) :effect (r ?y))))",
                                                         "h"),
                                        "h");
    auto problem = [&](const std::string &init, const std::string &goal, const pddl::Domain &d) {
        return pddl::parse_problem(pddl::read_sexpr("(define (problem t) (:domain d) (:objects "
                                                    "o1 o2) (:init " +
                                                        init + ") (:goal (and " + goal + ")))",
                                                    "p"),
                                   "p", d);
    };
    m.robot_problem = problem("(p o1)", "(r o1)", m.robot_domain);
    m.human_problem = problem("(p o1) (p o2) (s o2)", "(r o1) (q o2)", m.human_domain);
    std::vector<std::string> got;
    for (const auto &d : model_differences(m))
        got.push_back(d.text);
    // (s o2) in the human's init is read by the robot's precondition of a: relevant.
    EXPECT_EQ(got, (std::vector<std::string>{"-init (p o2)", "-init (s o2)", "-goal (q o2)",
                                             "+pre a (not (s ?x))", "-add a (r ?y)",
                                             "+del a (not (p ?x))", "+action b", "-action c"}));
    // Everything applied: the human's model has the robot's schemas, init and goal.
    std::vector<ModelDifference> all = model_differences(m);
    std::vector<int> every(all.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        every[i] = static_cast<int>(i);
    ModelPair told = told_models(m, all, every);
    ModelPair after{m.robot_domain, m.robot_problem, told.human_domain, told.human_problem};
    EXPECT_TRUE(model_differences(after, false).empty());
}

} // namespace
} // namespace envdesign::design
