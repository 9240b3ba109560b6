// RisingBounds: a configuration starts from the robot bounds of its subsets one
// robot-restricting modification smaller, and from nothing else. And the evaluator's floor
// jobs, which carry c_H* and its optimal plan up human-restricting modifications.

#include "design/search/rising_bounds.h"

#include "design/behaviour/explicability.h"
#include "design/evaluation/local_evaluator.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace envdesign::design {
namespace {

using Bounds = std::vector<std::optional<double>>;

TEST(RisingBounds, InheritsOnlyAcrossRobotRestrictingModifications) {
    RisingBounds memory({true, false, true}); // modification 1 may lower c_R*
    memory.remember({}, {10.0, std::nullopt});
    memory.remember({0}, {14.0, 9.0});
    memory.remember({1}, {3.0, 3.0});

    Bounds from_root;
    memory.inherit({2}, from_root);
    EXPECT_EQ(from_root, (Bounds{10.0, std::nullopt}));

    Bounds greatest{12.0, std::nullopt}; // {0, 2} has {0} and {2} below it: {0} is known
    memory.inherit({0, 2}, greatest);
    EXPECT_EQ(greatest, (Bounds{14.0, 9.0}));

    Bounds across_a_lane; // {0, 1} is {1} + 0 (inherits) and {0} + 1 (does not)
    memory.inherit({0, 1}, across_a_lane);
    EXPECT_EQ(across_a_lane, (Bounds{3.0, 3.0}));

    Bounds kept{20.0, 1.0}; // a greater bound already known stays
    memory.inherit({0, 2}, kept);
    EXPECT_EQ(kept, (Bounds{20.0, 9.0}));

    // Remembered again, one task at a time (the evaluator's floor jobs): each keeps its greatest.
    memory.remember({0}, {std::nullopt, 11.0});
    memory.remember({0}, {13.0, std::nullopt});
    Bounds merged;
    memory.inherit({0, 2}, merged);
    EXPECT_EQ(merged, (Bounds{14.0, 11.0}));
}

// The robot drives a-b-c-d (3 moves); people also see a-d and a-c. Their optimal plan is a-d (1).
// "sign-a-d" tells them a-d is closed (their optimum becomes a-c-d, 2); "sign-b-c" closes b-c
// for them, which their plan does not use.
TEST(RisingBounds, AFloorJobKeepsASubsetsHumanPlanWhereItIsStillValid) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("envdesign-kept-" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "domain.pddl") << R"pddl((define (domain roads) (:requirements :strips)
  (:predicates (at ?p) (connected ?from ?to))
  (:action move :parameters (?from ?to)
    :precondition (and (at ?from) (connected ?from ?to))
    :effect (and (not (at ?from)) (at ?to)))))pddl";
    std::string head = "(define (problem go) (:domain roads) (:objects a b c d)\n"
                       "  (:init (at a) (connected a b) (connected b c) (connected c d)";
    std::ofstream(dir / "robot.pddl") << head + ")\n  (:goal (at d)))";
    std::ofstream(dir / "human.pddl")
        << head + " (connected a d) (connected a c))\n  (:goal (at d)))";
    std::ofstream(dir / "spec.textproto") << R"spec(robot_domain: "domain.pddl"
task { name: "a-d" problem: "robot.pddl" human_problem: "human.pddl" }
modification { name: "sign-a-d" cost: 1 edit { model: HUMAN remove_init: "(connected a d)" } }
modification { name: "sign-b-c" cost: 1 edit { model: HUMAN remove_init: "(connected b c)" } }
)spec";
    DesignProblem problem = spec::load_design_problem((dir / "spec.textproto").string());
    LocalEvaluator evaluator(problem, 1);
    auto floor = [&](const Configuration &c) {
        JobAnswer answer{{}, 3.0, std::nullopt, {}};
        evaluator.floors(c, 0, Deadline{}, answer);
        return answer.ie_floor;
    };
    EXPECT_EQ(floor({}), std::exp(2.0)); // g(c_R* - c_H*) = exp(3 - 1)
    long long runs = evaluator.counters().planner_runs;
    EXPECT_EQ(floor({1}), std::exp(2.0)); // a-d still valid for people: kept, no search
    EXPECT_EQ(evaluator.counters().planner_runs, runs);
    EXPECT_EQ(floor({0}), std::exp(1.0)); // a-d closed: searched, a-c-d costs 2
    EXPECT_EQ(evaluator.counters().planner_runs, runs + 1);
    EXPECT_EQ(floor({0, 1}), std::exp(1.0)); // a-c-d, kept from {0}, still valid
    EXPECT_EQ(evaluator.counters().planner_runs, runs + 1);
    fs::remove_all(dir);
}

} // namespace
} // namespace envdesign::design
