// The two models (FLOORS.md "The two models"): robot edges are lanes; people also expect
// every sight line within --sight that no wall crosses; lengths in whole decimetres.

#include "floor/building_map.h"
#include "floor/floor_error.h"
#include "floor/floor_graph.h"

#include "map_text.h"

#include <gtest/gtest.h>

#include <chrono>

namespace envdesign::floor {
namespace {

using testing::MapText;

// p (0,0) -> m (3,3) -> q (6,0), both lanes two-way; p and q see each other across 6 m.
// Vertices 3 and 4 are free for walls and doors.
MapText detour(std::pair<double, double> w0, std::pair<double, double> w1) {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, "p"},
                  {3, 3, "m"},
                  {6, 0, "q"},
                  {w0.first, w0.second, ""},
                  {w1.first, w1.second, ""}};
    m.lanes = {{0, 1, true}, {1, 2, true}};
    return m;
}

FloorGraph graph_of(const MapText &m, double sight = 10) {
    return build_floor_graph(parse_building_map(m.yaml(), "t.building.yaml", {}), sight);
}

const std::vector<Edge> P_Q_BOTH_WAYS{{0, 2}, {2, 0}};

TEST(FloorGraph, ASightLineNotOnALaneIsHumanOnlyInBothDirections) {
    FloorGraph g = graph_of(detour({20, 20}, {21, 21}));
    EXPECT_EQ(g.robot.size(), 4u);
    EXPECT_EQ(g.human_only, P_Q_BOTH_WAYS);
}

TEST(FloorGraph, AWallAcrossTheSightLineRemovesIt) {
    MapText m = detour({3, -1}, {3, 1});
    m.walls = {{3, 4}};
    EXPECT_TRUE(graph_of(m).human_only.empty());
}

TEST(FloorGraph, AWallTouchingTheSightLineOnlyAtItsEndDoesNotBlock) {
    MapText m = detour({6, 0}, {6, 5}); // a wall from q's very point upwards
    m.walls = {{3, 4}};
    EXPECT_EQ(graph_of(m).human_only, P_Q_BOTH_WAYS);
    m.walls = {{2, 4}}; // the same wall drawn from q itself
    EXPECT_EQ(graph_of(m).human_only, P_Q_BOTH_WAYS);
}

TEST(FloorGraph, AWallRunningAlongTheSightLineBlocks) {
    MapText m = detour({2, 0}, {4, 0});
    m.walls = {{3, 4}};
    EXPECT_TRUE(graph_of(m).human_only.empty());
}

TEST(FloorGraph, DoorsNeverBlock) {
    MapText m = detour({3, -1}, {3, 1});
    m.doors = {{3, 4}};
    EXPECT_EQ(graph_of(m).human_only, P_Q_BOTH_WAYS);
}

TEST(FloorGraph, SightLinesLongerThanSightAreNotExpected) {
    MapText m = detour({20, 20}, {21, 21});
    EXPECT_TRUE(graph_of(m, 5.99).human_only.empty());
    EXPECT_EQ(graph_of(m, 6.0).human_only, P_Q_BOTH_WAYS); // |pq| <= sight
}

TEST(FloorGraph, AOneWayLaneLeavesItsReverseToPeople) {
    MapText m = detour({20, 20}, {21, 21});
    m.lanes = {{0, 1, std::nullopt}, {1, 2, true}, {2, 0, false}};
    // p->m is a lane, m->p only a sight line; q->p a lane, p->q only a sight line.
    std::vector<Edge> expected{{0, 2}, {1, 0}};
    EXPECT_EQ(graph_of(m).human_only, expected);
}

TEST(FloorGraph, LengthsAreDecimetresRoundedHalfAwayFromZeroAtLeastOne) {
    auto at = [](double x) { return Place{0, "", {x, 0}, {x, 0}}; };
    EXPECT_EQ(length_dm(at(0), at(0.25)), 3); // 2.5 dm -> 3
    EXPECT_EQ(length_dm(at(0), at(0.94)), 9);
    EXPECT_EQ(length_dm(at(0), at(0.04)), 1); // 0.4 dm, but at least 1
    EXPECT_EQ(length_dm(at(0), at(0)), 1);
    Place a{0, "", {0, 0}, {}}, b{1, "", {3, 4}, {}};
    EXPECT_EQ(length_dm(a, b), 50);
}

TEST(FloorGraph, ReachabilityFollowsTheRobotEdgesOnly) {
    MapText m = detour({20, 20}, {21, 21});
    m.lanes = {{0, 1, std::nullopt}, {1, 2, std::nullopt}};
    FloorGraph g = graph_of(m);
    EXPECT_TRUE(robot_reachable(g, 0)[2]);
    EXPECT_FALSE(robot_reachable(g, 2)[0]); // the sight line q->p is no way for the robot
}

TEST(FloorGraph, ManyPlacesAndWallsStayFastAndAgreeWithTheDirectTest) {
    // A 30 x 30 grid of places 1 m apart with a wall between each pair of columns' rows 10-20.
    Floor f;
    for (int i = 0; i < 900; ++i) {
        Point p{double(i % 30), double(i / 30)};
        f.places.push_back({i, "", p, p});
    }
    for (int c = 0; c < 29; ++c) {
        Segment w{{c + 0.5, 10}, {c + 0.5, 20}};
        f.walls.push_back(w);
        f.walls_raw.push_back(w);
    }
    std::vector<Edge> fast = sight_lines(f.places, f.walls, f.walls_raw, 3);
    std::size_t direct = 0;
    for (std::size_t i = 0; i < f.places.size(); ++i)
        for (std::size_t j = i + 1; j < f.places.size(); ++j) {
            Segment s{f.places[i].at, f.places[j].at};
            if (distance(s.a, s.b) > 3)
                continue;
            bool blocked = false;
            for (const auto &w : f.walls)
                blocked = blocked || sight_blocked(s, w);
            direct += !blocked;
        }
    EXPECT_EQ(fast.size(), direct);
    EXPECT_GT(direct, 5000u);
}

} // namespace
} // namespace envdesign::floor

namespace envdesign::floor {
namespace {

// MAX_PLACES places 1 m apart: 10 m of sight makes millions of sight lines (refused, fast);
// 1.5 m makes about 40,000, found in well under a second.
TEST(FloorGraph, ADenseFloorAtThePlaceLimitIsRefusedOrFastNeverUnbounded) {
    Floor f;
    for (int i = 0; i < static_cast<int>(MAX_PLACES); ++i) {
        Point p{double(i % 100), double(i / 100)};
        f.places.push_back({i, "", p, p});
    }
    for (int c = 0; c < 99; ++c) {
        Segment w{{c + 0.5, 10.2}, {c + 0.5, 20.2}};
        f.walls.push_back(w);
        f.walls_raw.push_back(w);
    }
    auto start = std::chrono::steady_clock::now();
    EXPECT_THROW(build_floor_graph(f, 10), FloorError);
    std::vector<Edge> lines = sight_lines(f.places, f.walls, f.walls_raw, 1.5);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GT(lines.size(), 35000u);
    EXPECT_LT(seconds, 10.0);
}

} // namespace
} // namespace envdesign::floor

namespace envdesign::floor {
namespace {

// Issue 21 (found writing fuzz_floor_inputs): ten thousand walls across the whole floor, a
// 64 KB map, were each entered in about three thousand cells of the wall grid: minutes and
// gigabytes before the first sight line. Cells now grow with the walls' total length.
TEST(FloorGraph, ManyLongWallsAreEnteredInFewCells) {
    Floor f;
    f.places = {{0, "", {0, 1}, {0, 1}}, {1, "", {5, 1}, {5, 1}}};
    for (int i = 0; i < 40000; ++i) {
        double y = i % 2 ? -1 : 3; // below and above the sight line, the floor's whole width
        Segment w{{-MAX_COORDINATE_M, y}, {MAX_COORDINATE_M, y}};
        f.walls.push_back(w);
        f.walls_raw.push_back(w);
    }
    auto start = std::chrono::steady_clock::now();
    std::vector<Edge> lines = sight_lines(f.places, f.walls, f.walls_raw, 10);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(lines, (std::vector<Edge>{{0, 1}}));
    EXPECT_LT(seconds, 5.0);
}

// Issue 21: every pair within sight is tested against the walls near it; places and walls
// dense enough to make that more than MAX_WALL_TESTS tests (here a budget of 100,000) are
// refused, not run for minutes.
TEST(FloorGraph, TooManyWallTestsAreRefused) {
    Floor f;
    for (int i = 0; i < 100; ++i) { // 4950 pairs within sight
        Point p{0.5 * (i % 10), 0.5 * (i / 10)};
        f.places.push_back({i, "", p, p});
    }
    for (int i = 0; i < 30; ++i) { // beside the places, blocking nothing
        Segment w{{12 + 0.01 * i, 0}, {12 + 0.01 * i, 1}};
        f.walls.push_back(w);
        f.walls_raw.push_back(w);
    }
    try {
        sight_lines(f.places, f.walls, f.walls_raw, 15, nullptr, 100000);
        ADD_FAILURE() << "4950 pairs x 31 tests were made";
    } catch (const FloorError &e) {
        EXPECT_NE(
            std::string(e.what()).find("more than 100000 tests of a sight line against a wall"),
            std::string::npos)
            << e.what();
    }
    // A third of the walls: 4950 x 11 tests, within the budget.
    f.walls.resize(10);
    f.walls_raw.resize(10);
    EXPECT_EQ(sight_lines(f.places, f.walls, f.walls_raw, 15, nullptr, 100000).size(), 4950u);
    EXPECT_EQ(sight_lines(f.places, f.walls, f.walls_raw, 15).size(), 4950u);
}

} // namespace
} // namespace envdesign::floor
