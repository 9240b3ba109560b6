// COST_OPTIMAL and COST_OPTIMAL_BEST_CASE (issue 14): IE_worst and IE_best from the
// optimal-plan graph and its product with the human model (design/behaviour/cost_optimal.h) against
// enumerating every cost-optimal plan with the plan validator (optimal_plans_brute_force.h),
// on seeded tiny tasks with zero-cost and equal-cost alternatives; and directed cases for
// the choices the header documents (zero-cost cycles, plans not valid for the human).

#include "optimal_plans_brute_force.h"

#include "design/behaviour/cost_optimal.h"
#include "design/behaviour/explicability.h"
#include "design/behaviour/optimal_plan_graph.h"
#include "design/behaviour/worst_case.h"
#include "ground/grounder.h"
#include "heuristics/make_heuristic.h"
#include "pddl/parser.h"
#include "pddl/sexpr.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

namespace envdesign::design {
namespace {

class Dice {
public:
    explicit Dice(unsigned seed) : engine_(seed * 104729u + 7u) {}
    int below(int n) { return static_cast<int>(engine_() % static_cast<unsigned>(n)); }
    bool percent(int p) { return below(100) < p; }

private:
    std::mt19937 engine_;
};

// One model of a tiny world: nodes joined by passages (move) and jumps (hop), a flag f0
// that can be switched on and off, and waiting (no effect). Costs are small and often 0.
struct World {
    int move = 1, hop = 2, flip_on = 0, flip_off = 0, wait = 0;
    bool has_hop = true, has_flip = true, has_wait = false;
    bool move_needs_flag_off = false; // move needs (not (on f0))
    std::set<std::pair<int, int>> conn, far;
};

struct TinyTask {
    int nodes = 3;
    int goal = 2;
    bool goal_flag = false; // the goal also needs (on f0)
    World robot, human;
};

std::string domain_text(const World &w) {
    std::ostringstream d;
    auto cost = [](int c) { return " (increase (total-cost) " + std::to_string(c) + ")"; };
    d << "(define (domain tiny) (:requirements :strips :typing :negative-preconditions "
         ":action-costs)\n (:types node flag) (:constants f0 - flag)\n"
         " (:predicates (at ?n - node) (conn ?a ?b - node) (far ?a ?b - node) (on ?f - flag))\n"
         " (:functions (total-cost) - number)\n"
         " (:action move :parameters (?a ?b - node) :precondition (and (at ?a) (conn ?a ?b)"
      << (w.move_needs_flag_off ? " (not (on f0))" : "") << ") :effect (and (not (at ?a)) (at ?b)"
      << cost(w.move) << "))\n";
    if (w.has_hop)
        d << " (:action hop :parameters (?a ?b - node) :precondition (and (at ?a) (far ?a ?b))"
             " :effect (and (not (at ?a)) (at ?b)"
          << cost(w.hop) << "))\n";
    if (w.has_flip)
        d << " (:action flip-on :parameters (?f - flag) :precondition (not (on ?f))"
             " :effect (and (on ?f)"
          << cost(w.flip_on)
          << "))\n (:action flip-off :parameters (?f - flag) :precondition (on ?f)"
             " :effect (and (not (on ?f))"
          << cost(w.flip_off) << "))\n";
    if (w.has_wait)
        d << " (:action wait :parameters (?n - node) :precondition (at ?n) :effect (and"
          << cost(w.wait) << "))\n";
    d << ")\n";
    return d.str();
}

std::string problem_text(const TinyTask &t, const World &w) {
    std::ostringstream p;
    p << "(define (problem tiny-1) (:domain tiny) (:objects";
    for (int n = 0; n < t.nodes; ++n)
        p << " n" << n;
    p << " - node)\n (:init (at n0) (= (total-cost) 0)";
    for (auto [a, b] : w.conn)
        p << " (conn n" << a << " n" << b << ")";
    for (auto [a, b] : w.far)
        p << " (far n" << a << " n" << b << ")";
    p << ")\n (:goal (and (at n" << t.goal << ")" << (t.goal_flag ? " (on f0)" : "")
      << "))\n (:metric minimize (total-cost)))\n";
    return p.str();
}

ModelPair models_of(const TinyTask &t) {
    ModelPair m;
    m.robot_domain =
        pddl::parse_domain(pddl::read_sexpr(domain_text(t.robot), "robot.pddl"), "robot.pddl");
    m.human_domain =
        pddl::parse_domain(pddl::read_sexpr(domain_text(t.human), "human.pddl"), "human.pddl");
    m.robot_problem = pddl::parse_problem(
        pddl::read_sexpr(problem_text(t, t.robot), "p-robot.pddl"), "p-robot.pddl", m.robot_domain);
    m.human_problem = pddl::parse_problem(
        pddl::read_sexpr(problem_text(t, t.human), "p-human.pddl"), "p-human.pddl", m.human_domain);
    return m;
}

TinyTask generate(unsigned seed) {
    Dice r(seed);
    TinyTask t;
    t.nodes = 3 + r.below(2);
    t.goal = 1 + r.below(t.nodes - 1);
    t.goal_flag = r.percent(25);
    World &w = t.robot;
    auto small = [&] { return r.percent(30) ? 0 : 1 + r.below(2); };
    w.move = r.percent(80) ? 1 : small();
    w.hop = small();
    w.flip_on = small(), w.flip_off = r.percent(60) ? 0 : small();
    w.wait = r.percent(70) ? 0 : 1;
    w.has_hop = r.percent(70), w.has_flip = r.percent(70) || t.goal_flag,
    w.has_wait = r.percent(40);
    w.move_needs_flag_off = r.percent(15);
    for (int a = 0; a < t.nodes; ++a)
        for (int b = 0; b < t.nodes; ++b)
            if (a != b) {
                if (r.percent(45))
                    w.conn.insert({a, b});
                if (r.percent(15))
                    w.far.insert({a, b});
            }
    World &h = t.human;
    h = w;
    // What people believe differs: costs, passages, actions, a rule on the flag.
    if (r.percent(50))
        h.move = small() + (r.percent(50) ? 1 : 0);
    if (r.percent(40))
        h.hop = small();
    if (r.percent(50))
        h.flip_on = small(), h.flip_off = small();
    if (r.percent(40))
        h.wait = 1 + r.below(2);
    if (r.percent(15))
        h.has_hop = false;
    if (r.percent(10))
        h.has_wait = false;
    if (r.percent(20))
        h.move_needs_flag_off = !h.move_needs_flag_off;
    for (int k = r.below(3); k > 0; --k) {
        int a = r.below(t.nodes), b = r.below(t.nodes);
        if (a == b)
            continue;
        if (h.conn.count({a, b}))
            h.conn.erase({a, b});
        else
            h.conn.insert({a, b});
    }
    return t;
}

bool same(double a, double b) { return std::isinf(a) ? std::isinf(b) : a == b; }

ObjectiveWeights weights(RobotBehaviour behaviour, Distance distance = Distance::EXP_COST_DIFF) {
    ObjectiveWeights w;
    w.behaviour = behaviour;
    w.distance = distance;
    return w;
}

// The reported plan must be an optimal robot plan with the reported human value.
void check_plan(const ModelPair &m, const TaskExplicability &e, unsigned seed, bool worst) {
    auto robot = validate::validate_plan(m.robot_domain, m.robot_problem, e.plan);
    ASSERT_TRUE(robot.valid) << "seed " << seed << ": " << robot.error;
    EXPECT_EQ(static_cast<double>(robot.cost), e.robot_cost) << "seed " << seed;
    auto human = validate::validate_plan(m.human_domain, m.human_problem, e.plan);
    if (std::isfinite(e.human_plan_cost)) {
        ASSERT_TRUE(human.valid) << "seed " << seed;
        EXPECT_EQ(static_cast<double>(human.cost), e.human_plan_cost) << "seed " << seed;
    } else if (worst && !human.valid) {
        SUCCEED(); // the witness of +inf: a plan people would not expect at all
    }
}

TEST(CostOptimal, WorstAndBestAgreeWithEnumeratingEveryOptimalPlan) {
    const int seeds = 150;
    int compared = 0, exhausted = 0, invalid = 0, unbounded = 0, several = 0, differ = 0;
    int finite_worst = 0, robot_unsolvable = 0;
    for (unsigned seed = 0; seed < seeds; ++seed) {
        TinyTask task = generate(seed);
        ModelPair m = models_of(task);
        auto reference = testing::enumerate_optimal_plans(m, 400000);
        if (reference.exhausted) {
            ++exhausted;
            continue;
        }
        ++compared;
        PlanCache planner(planning::PlannerOptions{});
        Distance distance = seed % 3 == 0 ? Distance::COST_DIFF : Distance::EXP_COST_DIFF;
        TaskExplicability worst = evaluate_cost_optimal(
            m, weights(RobotBehaviour::COST_OPTIMAL, distance), planner, Deadline{});
        TaskExplicability best = evaluate_cost_optimal(
            m, weights(RobotBehaviour::COST_OPTIMAL_BEST_CASE, distance), planner, Deadline{});
        if (std::isinf(reference.robot_optimal_cost) || std::isinf(reference.human_optimal_cost)) {
            robot_unsolvable += std::isinf(reference.robot_optimal_cost);
            EXPECT_EQ(worst.status, ExplicabilityStatus::INEXPLICABLE) << "seed " << seed;
            EXPECT_EQ(best.status, ExplicabilityStatus::INEXPLICABLE) << "seed " << seed;
            EXPECT_TRUE(std::isinf(worst.ie) && std::isinf(best.ie)) << "seed " << seed;
            continue;
        }
        invalid += reference.any_invalid;
        unbounded += reference.unbounded && !reference.any_invalid;
        several += reference.plans > 1;
        finite_worst += std::isfinite(reference.worst_human_cost());
        differ += !same(reference.worst_human_cost(), reference.best_human_cost());
        for (const auto *e : {&worst, &best}) {
            ASSERT_EQ(e->status, ExplicabilityStatus::SOLVED) << "seed " << seed;
            EXPECT_EQ(e->robot_cost, reference.robot_optimal_cost) << "seed " << seed;
            EXPECT_EQ(*e->human_optimal_cost, reference.human_optimal_cost) << "seed " << seed;
        }
        EXPECT_TRUE(same(worst.human_plan_cost, reference.worst_human_cost()))
            << "seed " << seed << ": worst " << worst.human_plan_cost << ", enumeration "
            << reference.worst_human_cost() << " (invalid " << reference.any_invalid
            << ", unbounded " << reference.unbounded << ")";
        EXPECT_TRUE(same(best.human_plan_cost, reference.best_human_cost()))
            << "seed " << seed << ": best " << best.human_plan_cost << ", enumeration "
            << reference.best_human_cost();
        EXPECT_TRUE(same(worst.ie, inexplicability(reference.worst_human_cost(),
                                                   reference.human_optimal_cost, distance)))
            << "seed " << seed;
        EXPECT_TRUE(same(best.ie, inexplicability(reference.best_human_cost(),
                                                  reference.human_optimal_cost, distance)))
            << "seed " << seed;
        check_plan(m, worst, seed, true);
        if (std::isfinite(best.human_plan_cost))
            check_plan(m, best, seed, false);
    }
    std::cout << "[ cost-optimal ] " << compared << " compared (" << exhausted
              << " over the enumeration budget); robot unsolvable " << robot_unsolvable
              << ", several optimal plans " << several << ", an invalid optimal plan " << invalid
              << ", unbounded by a cycle " << unbounded << ", finite worst " << finite_worst
              << ", worst != best " << differ << std::endl;
    EXPECT_GE(compared, 100);
    EXPECT_GE(several, 30);
    EXPECT_GE(invalid, 10);
    EXPECT_GE(unbounded, 3);
    EXPECT_GE(finite_worst, 30);
    EXPECT_GE(differ, 10);
}

// Hand-computed: n0 -> n1 -> n2 by two moves (robot 1 + 1) or one hop (robot 2): both
// optimal (c_R* = 2). People count a move 1 and a hop 5: c_H* = 2, the worst optimal plan
// is the hop (c_H = 5, IE = e^3), the best the moves (IE = e^0 = 1).
TinyTask two_ways() {
    TinyTask t;
    t.nodes = 3, t.goal = 2;
    t.robot.move = 1, t.robot.hop = 2, t.robot.has_flip = false;
    t.robot.conn = {{0, 1}, {1, 2}};
    t.robot.far = {{0, 2}};
    t.human = t.robot;
    t.human.hop = 5;
    return t;
}

TEST(CostOptimal, TwoOptimalPlansWorstAndBestByHand) {
    ModelPair m = models_of(two_ways());
    PlanCache planner(planning::PlannerOptions{});
    auto worst = evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL), planner, {});
    auto best =
        evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL_BEST_CASE), planner, {});
    EXPECT_EQ(worst.robot_cost, 2);
    EXPECT_EQ(worst.human_plan_cost, 5);
    EXPECT_DOUBLE_EQ(worst.ie, std::exp(3.0));
    EXPECT_EQ(worst.plan, std::vector<std::string>{"(hop n0 n2)"});
    EXPECT_EQ(best.human_plan_cost, 2);
    EXPECT_DOUBLE_EQ(best.ie, 1.0);
    EXPECT_EQ(best.plan, (std::vector<std::string>{"(move n0 n1)", "(move n1 n2)"}));
    EXPECT_EQ(*worst.optimal_actions,
              (std::vector<std::string>{"(hop n0 n2)", "(move n0 n1)", "(move n1 n2)"}));
}

// Waiting costs the robot nothing but people 1 a wait: the robot's optimal plans may wait
// any number of times, so the worst human cost has no bound (IE_worst = inf, the choice in
// worst_case.h); the best case never waits. If people count waiting as free, the cycle
// changes nothing.
TEST(CostOptimal, ZeroCostCycleCostlyToPeopleMakesTheWorstCaseInfinite) {
    TinyTask t = two_ways();
    t.robot.has_wait = t.human.has_wait = true;
    t.robot.wait = 0, t.human.wait = 1;
    ModelPair m = models_of(t);
    PlanCache planner(planning::PlannerOptions{});
    auto worst = evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL), planner, {});
    auto best =
        evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL_BEST_CASE), planner, {});
    EXPECT_EQ(worst.status, ExplicabilityStatus::SOLVED);
    EXPECT_TRUE(std::isinf(worst.ie));
    EXPECT_EQ(worst.robot_cost, 2);
    EXPECT_TRUE(std::find(worst.plan.begin(), worst.plan.end(), "(wait n0)") != worst.plan.end() ||
                std::find(worst.plan.begin(), worst.plan.end(), "(wait n1)") != worst.plan.end() ||
                std::find(worst.plan.begin(), worst.plan.end(), "(wait n2)") != worst.plan.end());
    EXPECT_DOUBLE_EQ(best.ie, 1.0);

    t.human.wait = 0;
    m = models_of(t);
    worst = evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL), planner, {});
    EXPECT_EQ(worst.human_plan_cost, 5);
}

// People do not know the hop: the hop plan is optimal for the robot and not valid for
// them, so IE_worst = inf while IE_best = 1; without the moves, IE_best = inf too.
TEST(CostOptimal, AnOptimalPlanPeopleCannotFollow) {
    TinyTask t = two_ways();
    t.human.has_hop = false;
    PlanCache planner(planning::PlannerOptions{});
    ModelPair m = models_of(t);
    auto worst = evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL), planner, {});
    auto best =
        evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL_BEST_CASE), planner, {});
    EXPECT_TRUE(std::isinf(worst.ie));
    EXPECT_EQ(worst.plan, std::vector<std::string>{"(hop n0 n2)"});
    EXPECT_DOUBLE_EQ(best.ie, 1.0);
    t.robot.move = 2; // only the hop is optimal now
    m = models_of(t);
    best = evaluate_cost_optimal(m, weights(RobotBehaviour::COST_OPTIMAL_BEST_CASE), planner, {});
    EXPECT_EQ(best.status, ExplicabilityStatus::SOLVED);
    EXPECT_TRUE(std::isinf(best.ie));
}

// A 20 x 20 grid, unit moves both ways, from one corner to the other: every cell lies on a
// shortest path and the optimal plans use exactly the 2 * 19 * 20 moves right and up, so
// the graph has 400 nodes and 760 edges (with the blind heuristic the search registers
// every state). A stop request or a memory limit of one byte gives LIMIT instead, in the
// graph and in the product.
TEST(CostOptimal, GridGraphIsExactAndLimitsStopIt) {
    const int side = 20;
    TinyTask t;
    t.nodes = side * side, t.goal = side * side - 1;
    t.robot.has_hop = t.robot.has_flip = false;
    for (int x = 0; x < side; ++x)
        for (int y = 0; y < side; ++y) {
            int n = x * side + y;
            if (x + 1 < side)
                t.robot.conn.insert({n, n + side}), t.robot.conn.insert({n + side, n});
            if (y + 1 < side)
                t.robot.conn.insert({n, n + 1}), t.robot.conn.insert({n + 1, n});
        }
    t.human = t.robot;
    ModelPair m = models_of(t);
    ground::GroundTask task = ground::ground(m.robot_domain, m.robot_problem, nullptr, {}, false);
    auto blind = heuristics::make_heuristic(heuristics::HeuristicKind::BLIND, task);
    OptimalPlanGraph graph = optimal_plan_graph(task, 2 * (side - 1), *blind, {});
    ASSERT_EQ(graph.status, OptimalPlanGraph::Status::SOLVED);
    EXPECT_EQ(graph.num_nodes(), side * side);
    EXPECT_EQ(graph.edges.size(), std::size_t(2 * (side - 1) * side));
    EXPECT_EQ(std::count(graph.goal.begin(), graph.goal.end(), true), 1);

    GraphLimits stop;
    stop.stop = [] { return true; };
    EXPECT_EQ(optimal_plan_graph(task, 2 * (side - 1), *blind, stop).status,
              OptimalPlanGraph::Status::LIMIT);
    GraphLimits tiny;
    tiny.memory_limit_bytes = 1;
    EXPECT_EQ(optimal_plan_graph(task, 2 * (side - 1), *blind, tiny).status,
              OptimalPlanGraph::Status::LIMIT);
    for (Case which : {Case::WORST, Case::BEST}) {
        EXPECT_EQ(human_cost_of_optimal_plans(graph, task, task, which, stop).status,
                  HumanCost::Status::LIMIT);
        HumanCost seen = human_cost_of_optimal_plans(graph, task, task, which, {});
        EXPECT_EQ(seen.status, HumanCost::Status::SOLVED);
        EXPECT_EQ(seen.cost, 2 * (side - 1)); // every monotone path costs people 38 too
    }
}

} // namespace
} // namespace envdesign::design
