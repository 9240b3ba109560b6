// Tasks (FLOORS.md "Tasks"): a CSV from,to,weight with its faults at FILE:LINE:COL, or every
// ordered pair of named places; pairs the robot cannot do are dropped with a warning.

#include "floor/building_map.h"
#include "floor/floor_error.h"
#include "floor/tasks.h"

#include "map_text.h"

#include "pddl/parse_error.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

using testing::MapText;

// v0 dock <-> v1 "" <-> v2 shelf, v2 -> v3 pack (one way), v4 "shelf" (a second shelf) <-> v1.
Floor site_floor() {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, "dock"}, {5, 0, ""}, {10, 0, "shelf"}, {15, 0, "pack"}, {5, 5, "shelf"}};
    m.lanes = {{0, 1, true}, {1, 2, true}, {2, 3}, {1, 4, true}};
    return parse_building_map(m.yaml(), "t.building.yaml", {});
}

std::string csv_error(const std::string &csv) {
    try {
        parse_tasks_csv(csv, "tasks.csv", site_floor());
    } catch (const pddl::ParseError &e) {
        return e.what();
    }
    return "no error";
}

TEST(Tasks, CsvRowsByLabelOrObjectInFileOrder) {
    auto tasks = parse_tasks_csv("from,to,weight\ndock,v2,3\r\n\nv3, dock ,1.5\n", "tasks.csv",
                                 site_floor());
    ASSERT_EQ(tasks.size(), 2u);
    EXPECT_EQ(tasks[0].name(), "v0-v2");
    EXPECT_EQ(*tasks[0].weight, 3);
    EXPECT_EQ(tasks[1].name(), "v3-v0");
    EXPECT_EQ(*tasks[1].weight, 1.5);
}

TEST(Tasks, CsvFaultsAreAtTheirLineAndColumn) {
    EXPECT_NE(csv_error("from,to\ndock,pack\n")
                  .find("tasks.csv:1:1: error: the first row must "
                        "be the header"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,dock,1\n")
                  .find("tasks.csv:2:6: error: the task "
                        "goes from v0 (dock) to itself"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,pack,1\nv0,v3,2\n")
                  .find("tasks.csv:3:1: error: "
                        "task v0-v3 is given twice"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,kitchen,1\n")
                  .find("tasks.csv:2:6: error: no "
                        "place 'kitchen'"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,v9,1\n").find("tasks.csv:2:6: error: no place 'v9'"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,shelf,1\n")
                  .find("tasks.csv:2:6: error: 'shelf' "
                        "names 2 places (v2, v4): use vI"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,pack,0\n")
                  .find("tasks.csv:2:11: error: weight 0 "
                        "is not a finite number > 0"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,pack,-2\n").find("tasks.csv:2:11:"),
              std::string::npos);
    // Issue 21 (fuzz_floor_inputs): two weights of 1.7e308 summed to inf, and every
    // probability the spec got was 0 (a spec the design command refuses).
    EXPECT_NE(csv_error("from,to,weight\ndock,pack,1e12\npack,dock,1.7e308\n")
                  .find("tasks.csv:3:11: error: weight 1.7e308 is not a finite number > 0 and "
                        "at most 1e12"),
              std::string::npos)
        << csv_error("from,to,weight\ndock,pack,1e12\npack,dock,1.7e308\n");
    EXPECT_NE(csv_error("from,to,weight\ndock,pack,lots\n")
                  .find("tasks.csv:2:11: error: weight "
                        "'lots' is not a number"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\ndock,pack\n")
                  .find("tasks.csv:2:1: error: a task is "
                        "'from,to,weight'"),
              std::string::npos);
    EXPECT_NE(csv_error("from,to,weight\n").find("no task"), std::string::npos);
}

TEST(Tasks, DefaultIsEveryOrderedPairOfNamedPlacesByVertexNumber) {
    auto tasks = default_tasks(site_floor());
    std::vector<std::string> names;
    for (const auto &t : tasks)
        names.push_back(t.name());
    // Named: v0 dock, v2 shelf, v3 pack, v4 shelf (v1 has no name).
    std::vector<std::string> expected{"v0-v2", "v0-v3", "v0-v4", "v2-v0", "v2-v3", "v2-v4",
                                      "v3-v0", "v3-v2", "v3-v4", "v4-v0", "v4-v2", "v4-v3"};
    EXPECT_EQ(names, expected);
    EXPECT_FALSE(tasks[0].weight);
}

TEST(Tasks, UnreachablePairsAreDroppedWithAWarningNamingThem) {
    Floor f = site_floor();
    FloorGraph g = build_floor_graph(f, 10);
    std::vector<std::string> warnings;
    auto kept = drop_unreachable(default_tasks(f), f, g, warnings);
    // pack (v3) is a dead end: nothing leaves it.
    EXPECT_EQ(kept.size(), 9u);
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0], "task v3-v0 dropped: the robot's lanes do not lead from v3 (pack) to "
                           "v0 (dock)");
    for (const auto &t : kept)
        EXPECT_NE(t.from, 3);
}

TEST(Tasks, NoNamedPlaceMeansNoDefaultTasks) {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, ""}, {5, 0, ""}};
    m.lanes = {{0, 1, true}};
    Floor f = parse_building_map(m.yaml(), "t", {});
    EXPECT_THROW(default_tasks(f), FloorError);
}

} // namespace
} // namespace envdesign::floor

namespace envdesign::floor {
namespace {

TEST(Tasks, ASpreadsheetsByteOrderMarkIsNoFault) {
    auto tasks = parse_tasks_csv("\xEF\xBB\xBF"
                                 "from,to,weight\ndock,pack,1\n",
                                 "t.csv", site_floor());
    ASSERT_EQ(tasks.size(), 1u);
    EXPECT_EQ(tasks[0].name(), "v0-v3");
}

TEST(Tasks, MoreDefaultPairsThanMaxTasksAreRefused) {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    for (int i = 0; i < 101; ++i) // 101 x 100 = 10100 ordered pairs
        m.vertices.push_back({double(i), 0, "p" + std::to_string(i)});
    for (int i = 0; i + 1 < 101; ++i)
        m.lanes.push_back({i, i + 1, true});
    Floor f = parse_building_map(m.yaml(), "t", {});
    try {
        default_tasks(f);
        FAIL() << "no error";
    } catch (const FloorError &e) {
        EXPECT_NE(std::string(e.what()).find("make 10100 tasks, more than 10000"),
                  std::string::npos);
    }
}

} // namespace
} // namespace envdesign::floor
