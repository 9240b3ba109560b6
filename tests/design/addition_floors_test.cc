// The floors that adding modifications can bring (addition_floors.h), on a floor small
// enough to work out by hand.
#include "design/search/addition_floors.h"

#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace envdesign::design {
namespace {

namespace fs = std::filesystem;

void write(const fs::path &path, const std::string &text) { std::ofstream(path) << text; }

// The robot drives a-b-c-d (3 moves); people also see a-d, b-d and c-a. Three lanes for the
// robot: a-d (a plan using it: a-d, 1), b-d (a-b-d, 2), c-a (a-b-c-a-d, 4).
DesignProblem three_lanes(const fs::path &dir) {
    fs::create_directories(dir);
    write(dir / "domain.pddl", R"pddl((define (domain lanes) (:requirements :strips :typing)
  (:types place) (:predicates (at ?p - place) (connected ?from ?to - place))
  (:action move :parameters (?from ?to - place)
    :precondition (and (at ?from) (connected ?from ?to))
    :effect (and (not (at ?from)) (at ?to)))))pddl");
    std::string head = "(define (problem go) (:domain lanes) (:objects a b c d - place)\n"
                       "  (:init (at a) (connected a b) (connected b c) (connected c d)";
    write(dir / "robot.pddl", head + ")\n  (:goal (at d)))");
    write(dir / "human.pddl",
          head + " (connected a d) (connected b d) (connected c a))\n  (:goal (at d)))");
    write(dir / "spec.textproto", R"spec(robot_domain: "domain.pddl"
task { name: "a-d" problem: "robot.pddl" human_problem: "human.pddl" }
modification { name: "lane-c-a" cost: 1 edit { model: ROBOT add_init: "(connected c a)" } }
modification { name: "lane-a-d" cost: 1 edit { model: ROBOT add_init: "(connected a d)" } }
modification { name: "lane-b-d" cost: 1 edit { model: ROBOT add_init: "(connected b d)" } }
distance: COST_DIFF
)spec");
    return spec::load_design_problem((dir / "spec.textproto").string());
}

TEST(AdditionFloors, EachLaneLowersTheFloorToItsCheapestPlan) {
    fs::path dir = fs::temp_directory_path() / ("envdesign-floors-" + std::to_string(getpid()));
    DesignProblem problem = three_lanes(dir);
    TouchIndex index(problem);
    for (int m = 0; m < 3; ++m)
        EXPECT_TRUE(index.of(m).adding && !index.of(m).restricting) << m;
    std::string why;
    // Floors with no modification: c_H(pi) = 3 (a-b-c-d), c_R* = 3.
    auto floors = addition_floors(problem, {0, 1, 2}, {3.0}, {3.0}, Deadline{}, why);
    ASSERT_TRUE(floors) << why;
    auto as_pairs = [](const std::vector<UseFloor> &below) {
        std::vector<std::pair<int, double>> out;
        for (const UseFloor &f : below)
            out.emplace_back(f.modification, f.cost);
        return out;
    };
    // lane-c-a's cheapest plan costs 4, above the floor: it cannot lower it, not listed.
    std::vector<std::pair<int, double>> expected{{1, 1.0}, {2, 2.0}};
    EXPECT_EQ(as_pairs(floors->below[0]), expected);
    EXPECT_EQ(as_pairs(floors->robot_below[0]), expected);
    // A floor of 1 (the least any plan costs): nothing can lower it, and no lane is searched.
    auto low = addition_floors(problem, {0, 1, 2}, {0.5}, {std::nullopt}, Deadline{}, why);
    ASSERT_TRUE(low) << why;
    EXPECT_TRUE(low->below[0].empty());
    EXPECT_TRUE(low->robot_below[0].empty());
    EXPECT_EQ(low->searches, 1);
    fs::remove_all(dir);
}

} // namespace
} // namespace envdesign::design
