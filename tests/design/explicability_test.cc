// The most explicable plan and its IE, against values worked out by hand (comments) and
// against a brute-force enumeration checked by the independent plan validator.

#include "brute_force.h"
#include "design/behaviour/explicability.h"
#include "design/model/compilation.h"
#include "example_paths.h"
#include "generated_models.h"
#include "pddl/parser.h"
#include "validate/plan_validator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace envdesign::design {
namespace {

ModelPair load(const std::string &dir, const std::string &domain, const std::string &robot,
               const std::string &human) {
    ModelPair m;
    m.robot_domain = pddl::parse_domain_file(dir + domain);
    m.human_domain = m.robot_domain;
    m.robot_problem = pddl::parse_problem_file(dir + robot, m.robot_domain);
    m.human_problem = pddl::parse_problem_file(dir + human, m.human_domain);
    return m;
}

TaskExplicability evaluate(const ModelPair &m, Distance d = Distance::EXP_COST_DIFF,
                           bool solve_human_anyway = false) {
    PlanCache planner(planning::PlannerOptions{});
    return evaluate_explicability(m, d, planner, Deadline{}, solve_human_anyway);
}

// Robot: s-x-g (robot cost 5+5, human cost 2+2) or s-y-g (robot 1+1, human 1+3). The human
// also believes in s-g (human cost 1). Both robot routes cost the human 4: the robot's
// cheaper one, via y, is the most explicable plan. IE = exp(4 - 1).
TEST(Explicability, NonUnitCostsPickTheRobotsCheapestAmongTheMostExplicable) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    TaskExplicability e = evaluate(m);
    ASSERT_EQ(e.status, ExplicabilityStatus::SOLVED);
    EXPECT_EQ(e.plan, (std::vector<std::string>{"(drive s y)", "(drive y g)"}));
    EXPECT_EQ(e.human_plan_cost, 4);
    EXPECT_EQ(e.robot_cost, 2);
    EXPECT_EQ(e.human_optimal_cost, 1);
    EXPECT_DOUBLE_EQ(e.ie, std::exp(3.0));
}

TEST(Explicability, CostDiffIsTheDifferenceItself) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    TaskExplicability e = evaluate(m, Distance::COST_DIFF);
    EXPECT_DOUBLE_EQ(e.ie, 3.0);
}

// Without a metric the human charges 1 a step: both routes cost 2, c_H* = 1, IE = e.
TEST(Explicability, AModelWithoutMetricCostsOnePerAction) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "unit.pddl");
    TaskExplicability e = evaluate(m);
    EXPECT_EQ(e.human_plan_cost, 2);
    EXPECT_EQ(e.robot_cost, 2);
    EXPECT_EQ(e.human_optimal_cost, 1);
    EXPECT_DOUBLE_EQ(e.ie, std::exp(1.0));
}

// The robot can only take s-g and the observers believe in no road at all: neither P_H nor
// P_mod has a plan.
TEST(Explicability, NoPlanForBothModelsMeansInfiniteIE) {
    ModelPair m = load(ROADS, "domain.pddl", "robot-only.pddl", "human-no-road.pddl");
    TaskExplicability e = evaluate(m, Distance::EXP_COST_DIFF, true);
    EXPECT_EQ(e.status, ExplicabilityStatus::INEXPLICABLE);
    EXPECT_TRUE(std::isinf(e.ie));
    EXPECT_TRUE(std::isinf(e.robot_cost));
    ASSERT_TRUE(e.human_optimal_cost.has_value());
    EXPECT_TRUE(std::isinf(*e.human_optimal_cost));
    EXPECT_TRUE(e.plan.empty());
}

// P_H has a plan (s-g, cost 1) but the robot cannot take it, and the robot's roads are
// unknown to the human: P_mod has no plan, IE is infinite, c_H* is still reported.
TEST(Explicability, HumanSolvableButNoCommonPlanIsInfinite) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "robot-only.pddl");
    TaskExplicability e = evaluate(m, Distance::COST_DIFF, true);
    EXPECT_EQ(e.status, ExplicabilityStatus::INEXPLICABLE);
    EXPECT_TRUE(std::isinf(e.ie));
    EXPECT_EQ(e.human_optimal_cost, 1);
}

TEST(Explicability, ThePlanIsValidInBothModelsWithTheReportedCosts) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    TaskExplicability e = evaluate(m);
    auto robot = validate::validate_plan(m.robot_domain, m.robot_problem, e.plan);
    auto human = validate::validate_plan(m.human_domain, m.human_problem, e.plan);
    ASSERT_TRUE(robot.valid) << robot.error;
    ASSERT_TRUE(human.valid) << human.error;
    EXPECT_EQ(robot.cost, e.robot_cost);
    EXPECT_EQ(human.cost, e.human_plan_cost);
}

struct RoadCase {
    std::string robot, human;
};

// Readable test names in ctest output instead of the parameter's bytes.
void PrintTo(const RoadCase &c, std::ostream *out) { *out << c.robot << " vs " << c.human; }

class AgainstBruteForce : public ::testing::TestWithParam<RoadCase> {};

TEST_P(AgainstBruteForce, SameCostsAsEnumeratingEverySequence) {
    ModelPair m = load(ROADS, "domain.pddl", GetParam().robot, GetParam().human);
    testing::BruteForce expected = testing::brute_force_explicability(m, 3);
    TaskExplicability e = evaluate(m, Distance::COST_DIFF, true);
    EXPECT_EQ(e.human_plan_cost, expected.human_plan_cost);
    EXPECT_EQ(e.robot_cost, expected.robot_cost);
    EXPECT_EQ(e.human_optimal_cost, expected.human_optimal_cost);
}

INSTANTIATE_TEST_SUITE_P(Roads, AgainstBruteForce,
                         ::testing::Values(RoadCase{"robot.pddl", "human.pddl"},
                                           RoadCase{"robot.pddl", "unit.pddl"},
                                           RoadCase{"human.pddl", "robot.pddl"},
                                           RoadCase{"unit.pddl", "human.pddl"},
                                           RoadCase{"robot-only.pddl", "human.pddl"},
                                           RoadCase{"robot.pddl", "robot-only.pddl"}));

// The restaurant (examples/restaurant): serving G1 the robot goes around the tables
// (pick-up, 5 moves, put-down = 7); the observers expect the way between them (5).
TEST(Explicability, RestaurantAgainstBruteForce) {
    for (const std::string task : {"g1"}) { // g2 needs 8 steps: too long to enumerate
        ModelPair m = load(RESTAURANT, "domain.pddl", "serve-" + task + ".pddl",
                           "serve-" + task + "-human.pddl");
        testing::BruteForce expected = testing::brute_force_explicability(m, 7);
        TaskExplicability e = evaluate(m);
        EXPECT_EQ(e.human_plan_cost, expected.human_plan_cost) << task;
        EXPECT_EQ(e.robot_cost, expected.robot_cost) << task;
        EXPECT_EQ(e.human_optimal_cost, expected.human_optimal_cost) << task;
    }
}

// Seeded pairs of every kind of model difference (explaining_generator.h): the evaluation
// agrees with the enumeration of every sequence, whether the human's optimal plan answered
// P_mod (it is valid there and both models charge alike: one search, P_H's) or P_mod was
// searched. Both ways must occur.
TEST(Explicability, GeneratedPairsAgainstBruteForceWithAndWithoutTheHumansPlan) {
    int answered_by_human_plan = 0, searched = 0;
    for (unsigned seed = 0; seed < 60; ++seed) {
        ModelPair m = testing::models_of(testing::generate_pair(seed));
        PlanCache planner(planning::PlannerOptions{});
        TaskExplicability e =
            evaluate_explicability(m, Distance::COST_DIFF, planner, Deadline{}, true);
        // Every step costs people at least 1, so no plan cheaper for them is longer.
        int steps = std::isfinite(e.human_plan_cost) ? static_cast<int>(e.human_plan_cost) : 6;
        testing::BruteForce expected = testing::brute_force_explicability(m, steps);
        EXPECT_EQ(e.human_optimal_cost, expected.human_optimal_cost) << "seed " << seed;
        if (e.status != ExplicabilityStatus::SOLVED) {
            EXPECT_TRUE(std::isinf(expected.human_plan_cost)) << "seed " << seed;
            continue;
        }
        EXPECT_EQ(e.human_plan_cost, expected.human_plan_cost) << "seed " << seed;
        EXPECT_EQ(e.robot_cost, expected.robot_cost) << "seed " << seed;
        auto robot = validate::validate_plan(m.robot_domain, m.robot_problem, e.plan);
        auto human = validate::validate_plan(m.human_domain, m.human_problem, e.plan);
        EXPECT_TRUE(robot.valid && human.valid) << "seed " << seed;
        EXPECT_EQ(robot.cost, e.robot_cost) << "seed " << seed;
        EXPECT_EQ(human.cost, e.human_plan_cost) << "seed " << seed;
        (planner.counters().planner_runs == 1 ? answered_by_human_plan : searched) += 1;
    }
    std::cout << answered_by_human_plan << " answered by the human's plan, " << searched
              << " searched\n";
    EXPECT_GT(answered_by_human_plan, 5);
    EXPECT_GT(searched, 5);
}

// A tool people do not know of (t2 is in the robot's problem only): P_mod may use it, so its
// plans need not be plans of P_H, and the human's optimal plan (fix t1, use t1: 6) is not most
// explicable although it is valid in P_mod. The most explicable plan is (use t2): 1.
TEST(Explicability, AnObjectOnlyTheRobotKnowsKeepsTheSearchOfPmod) {
    const std::string domain = R"((define (domain tools)
  (:requirements :strips :typing :negative-preconditions :action-costs)
  (:types tool)
  (:predicates (broken ?t - tool) (done))
  (:functions (total-cost) - number)
  (:action use :parameters (?t - tool) :precondition (not (broken ?t))
    :effect (and (done) (increase (total-cost) 1)))
  (:action fix :parameters (?t - tool) :precondition (broken ?t)
    :effect (and (not (broken ?t)) (increase (total-cost) 5)))))";
    auto problem = [](const std::string &objects) {
        return "(define (problem p) (:domain tools) (:objects " + objects +
               " - tool) (:init (broken t1) (= (total-cost) 0)) (:goal (done))"
               " (:metric minimize (total-cost)))";
    };
    ModelPair m;
    m.robot_domain = pddl::parse_domain_text(domain, "domain.pddl");
    m.human_domain = m.robot_domain;
    m.robot_problem = pddl::parse_problem_text(problem("t1 t2"), "robot.pddl", m.robot_domain);
    m.human_problem = pddl::parse_problem_text(problem("t1"), "human.pddl", m.human_domain);
    TaskExplicability e = evaluate(m, Distance::COST_DIFF);
    ASSERT_EQ(e.status, ExplicabilityStatus::SOLVED);
    EXPECT_EQ(e.human_optimal_cost, 6);
    EXPECT_EQ(e.plan, (std::vector<std::string>{"(use t2)"}));
    EXPECT_EQ(e.human_plan_cost, 1);
    EXPECT_DOUBLE_EQ(e.ie, 5.0);
}

TEST(Compilation, RenamesFluentsAndKeepsBothModelsConditions) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    CompiledTask c = compile_explicable(m);
    ASSERT_EQ(c.domain.actions.size(), 1u);
    const pddl::Action &drive = c.domain.actions[0];
    std::vector<std::string> pre;
    for (const auto &l : drive.precondition)
        pre.push_back(l.to_string());
    EXPECT_EQ(pre, (std::vector<std::string>{"(r-at ?from)", "(r-road ?from ?to)", "(h-at ?from)",
                                             "(h-road ?from ?to)"}));
    EXPECT_EQ(drive.effect.size(), 6u);
    ASSERT_EQ(drive.costs.size(), 1u);
    EXPECT_EQ(drive.costs[0].function->predicate, "h-road-cost");
    EXPECT_EQ(drive.secondary_costs[0].function->predicate, "r-road-cost");
    EXPECT_EQ(c.problem.goal.size(), 2u);
    EXPECT_TRUE(c.problem.minimize_total_cost);
    EXPECT_EQ(c.problem.function_values.size(), 4u + 5u);
}

// The human's domain names the parameters differently and lacks the robot's `teleport`:
// P_mod renames the human's variables by position and has no `teleport` (no plan with it
// is valid for the human).
TEST(Compilation, ActionsMatchByNameAndParametersByPosition) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    m.human_domain = pddl::parse_domain(pddl::read_sexpr(R"((define (domain roads)
      (:requirements :strips :typing :action-costs)
      (:types place)
      (:predicates (at ?p - place) (road ?from ?to - place) (visited ?p - place))
      (:functions (total-cost) - number (road-cost ?from ?to - place) - number)
      (:action drive :parameters (?a ?b - place)
        :precondition (and (at ?a) (road ?a ?b))
        :effect (and (at ?b) (not (at ?a)) (increase (total-cost) (road-cost ?a ?b))))))",
                                                         "human.pddl"),
                                        "human.pddl");
    m.human_problem = pddl::parse_problem_file(ROADS + "human.pddl", m.human_domain);
    pddl::Action teleport = m.robot_domain.actions[0];
    teleport.name = "teleport";
    m.robot_domain.actions.push_back(teleport);
    CompiledTask c = compile_explicable(m);
    ASSERT_EQ(c.domain.actions.size(), 1u);
    std::vector<std::string> pre;
    for (const auto &l : c.domain.actions[0].precondition)
        pre.push_back(l.to_string());
    EXPECT_EQ(pre, (std::vector<std::string>{"(r-at ?from)", "(r-road ?from ?to)", "(h-at ?from)",
                                             "(h-road ?from ?to)"}));
    EXPECT_EQ(c.domain.actions[0].costs[0].function->to_string(), "(h-road-cost ?from ?to)");
    TaskExplicability e = evaluate(m);
    EXPECT_EQ(e.robot_cost, 2);
    EXPECT_EQ(e.human_plan_cost, 4);
}

TEST(Compilation, ParameterCountsMustAgree) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    m.human_domain.actions[0].parameters.pop_back();
    EXPECT_THROW(compile_explicable(m), pddl::ParseError);
}

// The IE floor (explicability.h): g(c_R* - c_H*), the least IE below zero or where a cost is
// unknown.
TEST(IeFloor, IsTheDistanceOfTheTwoOptimaWhenTheRobotsIsDearer) {
    EXPECT_DOUBLE_EQ(ie_floor(5, 2, Distance::EXP_COST_DIFF), std::exp(3.0));
    EXPECT_DOUBLE_EQ(ie_floor(5, 2, Distance::COST_DIFF), 3.0);
    EXPECT_EQ(ie_floor(2, 5, Distance::EXP_COST_DIFF), 1.0);
    EXPECT_EQ(ie_floor(2, 5, Distance::COST_DIFF), 0.0);
    EXPECT_EQ(ie_floor(INF, 2, Distance::EXP_COST_DIFF), 1.0);
    EXPECT_EQ(ie_floor(5, INF, Distance::COST_DIFF), 0.0);
}

// Costs from a function dominate only where both problems give the same values; a model
// without a metric costs 1 a step, which a function term does not dominate.
TEST(IeFloor, HumanCostsDominateOnlyWhereEveryActionCostsPeopleAtLeastTheRobots) {
    ModelPair m = load(ROADS, "domain.pddl", "robot.pddl", "human.pddl");
    EXPECT_FALSE(human_costs_dominate(m.robot_domain, m.robot_problem, m.human_domain,
                                      m.human_problem)); // other road costs
    EXPECT_TRUE(human_costs_dominate(m.robot_domain, m.robot_problem, m.human_domain,
                                     m.robot_problem)); // the same costs
    ModelPair unit = load(ROADS, "domain.pddl", "unit.pddl", "human.pddl");
    EXPECT_FALSE(human_costs_dominate(unit.robot_domain, unit.robot_problem, unit.human_domain,
                                      unit.human_problem)); // 1 a step against road costs
    EXPECT_TRUE(human_costs_dominate(unit.robot_domain, unit.robot_problem, unit.human_domain,
                                     unit.robot_problem)); // 1 a step both
    pddl::Domain dearer = unit.human_domain;               // people charge 2 a step, the robot 1
    dearer.actions[0].costs = {pddl::CostExpression{2, std::nullopt}};
    pddl::Problem metric = unit.robot_problem;
    metric.minimize_total_cost = true;
    EXPECT_TRUE(human_costs_dominate(unit.robot_domain, unit.robot_problem, dearer, metric));
    EXPECT_FALSE(human_costs_dominate(dearer, metric, unit.human_domain, unit.robot_problem));
}

// On the paper's Blocksworld every robot plan costs people what it costs the robot, so the
// most explicable plan is an optimal robot plan and the floor is the task's IE exactly:
// problem 02, the 4-block state of instance 1 with the goal of instance 2: c_R* 12, c_H* 6
// (people think the robot carries towers whole), IE e^6.
TEST(IeFloor, IsTheIeOfTheMostExplicablePlanOnThePapersBlocksworld) {
    ModelPair m = testing::paper_blocksworld("02/init-4-1-goal-4-2.pddl");
    ASSERT_TRUE(
        human_costs_dominate(m.robot_domain, m.robot_problem, m.human_domain, m.human_problem));
    PlanCache planner(planning::PlannerOptions{});
    PlanOutcome robot = solve_model(m.robot_domain, m.robot_problem, planner, Deadline{});
    TaskExplicability e = evaluate(m);
    ASSERT_EQ(robot.status, PlanStatus::SOLVED);
    ASSERT_EQ(e.status, ExplicabilityStatus::SOLVED);
    EXPECT_EQ(robot.cost, 12);
    EXPECT_EQ(*e.human_optimal_cost, 6);
    EXPECT_DOUBLE_EQ(e.ie, std::exp(6.0));
    EXPECT_DOUBLE_EQ(ie_floor(robot.cost, *e.human_optimal_cost, Distance::EXP_COST_DIFF), e.ie);
}

} // namespace
} // namespace envdesign::design
