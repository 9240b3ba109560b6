// Reading an Open-RMF building map (FLOORS.md "Reading an Open-RMF building map"): level and
// graph, metres, places; and the faults of a map, each at FILE:LINE:COL.

#include "floor/building_map.h"

#include "map_text.h"

#include "pddl/parse_error.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

using testing::MapText;

MapText pixel_map() {
    MapText m;
    m.vertices = {{0, 0, "a"}, {100, 0, ""}, {100, 50, "b"}, {300, 300, "far"}};
    m.lanes = {{0, 1, true}, {1, 2, false}};
    m.measurements = {{0, 1, 5.0}, {1, 2, 2.0}};
    return m;
}

Floor read(const MapText &m, BuildingMapOptions options = {}) {
    return parse_building_map(m.yaml(), "site.building.yaml", options);
}

std::string error_of(const std::string &yaml, BuildingMapOptions options = {}) {
    try {
        parse_building_map(yaml, "site.building.yaml", options);
    } catch (const pddl::ParseError &e) {
        return e.what();
    }
    return "no error";
}

TEST(BuildingMap, ScaleIsTheMeanOfTheMeasurementsAndYIsFlipped) {
    Floor f = read(pixel_map());
    // 5 m over 100 px and 2 m over 50 px: 0.05 and 0.04 metres a pixel, mean 0.045.
    EXPECT_DOUBLE_EQ(f.scale, 0.045);
    ASSERT_EQ(f.places.size(), 3u);
    EXPECT_EQ(f.places[2].vertex, 2);
    EXPECT_DOUBLE_EQ(f.places[2].at.x, 4.5);
    EXPECT_DOUBLE_EQ(f.places[2].at.y, -2.25);
    EXPECT_DOUBLE_EQ(f.places[2].raw.y, 50);
}

TEST(BuildingMap, ReferenceImageIsPixelsLikeNoCoordinateSystem) {
    MapText m = pixel_map();
    m.coordinate_system = "reference_image";
    EXPECT_DOUBLE_EQ(read(m).places[2].at.y, -2.25);
}

TEST(BuildingMap, CartesianMetersAreMetresAsWritten) {
    MapText m = pixel_map();
    m.coordinate_system = "cartesian_meters";
    m.measurements.clear(); // not needed in metres
    Floor f = read(m);
    EXPECT_DOUBLE_EQ(f.scale, 1);
    EXPECT_DOUBLE_EQ(f.places[2].at.x, 100);
    EXPECT_DOUBLE_EQ(f.places[2].at.y, 50);
}

TEST(BuildingMap, Wgs84AndWebMercatorAreNotSupported) {
    for (std::string system : {"wgs84", "web_mercator"}) {
        MapText m = pixel_map();
        m.coordinate_system = system;
        std::string e = error_of(m.yaml());
        EXPECT_NE(e.find("site.building.yaml:1:20: error: coordinate system '" + system +
                         "' is not supported"),
                  std::string::npos)
            << e;
    }
}

TEST(BuildingMap, PixelsWithoutAMeasurementAreRefused) {
    MapText m = pixel_map();
    m.measurements.clear();
    EXPECT_NE(error_of(m.yaml()).find("has no measurements"), std::string::npos);
}

TEST(BuildingMap, PlacesAreTheVerticesOnLanesOfTheGraphNotSelfLanes) {
    MapText m = pixel_map();
    m.lanes.push_back({3, 3, true});    // a self-lane: v3 is no place
    m.lanes.push_back({2, 3, true, 1}); // another graph
    Floor f = read(m);
    ASSERT_EQ(f.places.size(), 3u);
    EXPECT_EQ(f.places[0].name, "a");
    EXPECT_EQ(f.places[1].name, "");
    for (const Edge &e : f.lanes)
        EXPECT_NE(e.from, e.to);
    Floor g1 = read(m, {std::nullopt, 1});
    ASSERT_EQ(g1.places.size(), 2u);
    EXPECT_EQ(g1.places[1].vertex, 3);
}

TEST(BuildingMap, RobotEdgesAreLanesAndTheirReverseOnlyWhenBidirectional) {
    MapText m = pixel_map();
    m.lanes = {{0, 1, true}, {1, 2, false}, {2, 3, std::nullopt}};
    Floor f = read(m);
    std::vector<Edge> expected{{0, 1}, {1, 0}, {1, 2}, {2, 3}};
    EXPECT_EQ(f.lanes, expected); // sorted; absent bidirectional is one way
}

TEST(BuildingMap, SeveralLevelsNeedOneChosenAndUnknownOnesAreListed) {
    std::string two = pixel_map().yaml();
    // A second level: the same content under L2.
    std::string body =
        two.substr(two.find("    elevation"), two.find("lifts:") - two.find("    elevation"));
    std::string yaml = two.substr(0, two.find("lifts:")) + "  L2:\n" + body + "lifts: {}\n";
    EXPECT_NE(error_of(yaml).find("2 levels and none chosen (--level): the levels are: L1, L2"),
              std::string::npos)
        << error_of(yaml);
    EXPECT_NE(error_of(yaml, {"L9", 0}).find("no level 'L9'; the levels are: L1, L2"),
              std::string::npos);
    EXPECT_EQ(parse_building_map(yaml, "x", {"L2", 0}).level, "L2");
}

TEST(BuildingMap, AnUnknownGraphListsTheGraphsThere) {
    MapText m = pixel_map();
    m.lanes.push_back({2, 3, true, 4});
    EXPECT_NE(error_of(m.yaml(), {std::nullopt, 2})
                  .find("no lane of graph 2 on this level; its "
                        "graphs are: 0, 4"),
              std::string::npos);
}

TEST(BuildingMap, MalformedYamlIsReportedWhereTheParserStopped) {
    std::string e = error_of("levels:\n  L1:\n    vertices: [[0, 0, 0, \"a\"]\n    lanes: []\n");
    EXPECT_NE(e.find("site.building.yaml:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("malformed YAML"), std::string::npos) << e;
}

TEST(BuildingMap, MissingKeysAndBadValuesNameTheirLine) {
    EXPECT_NE(error_of("name: building\n")
                  .find("site.building.yaml:1:1: error: the building map "
                        "has no 'levels'"),
              std::string::npos);
    MapText m = pixel_map();
    m.lanes.push_back({2, 9, true});
    std::string e = error_of(m.yaml());
    EXPECT_NE(e.find(":12:13: error: the lane's end 9 is not a vertex (the level has 4)"),
              std::string::npos)
        << e << m.yaml();
}

TEST(BuildingMap, NanAndHugeCoordinatesAreRefused) {
    MapText m = pixel_map();
    std::string yaml = m.yaml();
    std::string nan = yaml;
    nan.replace(nan.find("[100, 50"), 8, "[.nan, 50");
    EXPECT_NE(error_of(nan).find("vertex 2's x is not finite"), std::string::npos) << error_of(nan);
    m.vertices[3] = {3e7, 0, "far"}; // 3e7 px at 0.045 m/px = 1.35e6 m
    EXPECT_NE(error_of(m.yaml()).find("vertex 3 lies beyond 1000000 m"), std::string::npos);
}

TEST(BuildingMap, DeeplyNestedYamlIsRefusedNotRecursedInto) {
    std::string deep = "levels: " + std::string(100000, '[') + "\n";
    EXPECT_NE(error_of(deep).find("nested deeper than 64"), std::string::npos);
}

TEST(BuildingMap, WallsAreReadInBothFrames) {
    MapText m = pixel_map();
    m.walls = {{0, 2}};
    Floor f = read(m);
    ASSERT_EQ(f.walls.size(), 1u);
    EXPECT_DOUBLE_EQ(f.walls_raw[0].b.x, 100);
    EXPECT_DOUBLE_EQ(f.walls[0].b.y, -2.25);
}

} // namespace
} // namespace envdesign::floor

namespace envdesign::floor {
namespace {

TEST(BuildingMap, ALevelGivenTwiceAndAGraphNumberOutOfRangeAreRefused) {
    EXPECT_NE(error_of("levels: {L1: {}, L1: {}}\n").find("1:18: error: level 'L1' is given twice"),
              std::string::npos)
        << error_of("levels: {L1: {}, L1: {}}\n");
    MapText m = pixel_map();
    std::string yaml = m.yaml();
    yaml.replace(yaml.find("graph_idx: [2, 0]"), 17, "graph_idx: [2, 99999999999]");
    EXPECT_NE(error_of(yaml).find("graph_idx 99999999999 is not a graph number"),
              std::string::npos);
}

// Issue 21, found writing fuzz_floor_inputs: a place's label and the level's name went as
// they were into the comments of the spec and the problems (a newline ended the comment, and
// the rest was read as spec fields or PDDL) and into floor.json (bytes that are not UTF-8 made
// the import throw a JSON library error, no FILE:LINE:COL).
TEST(BuildingMap, NamesThatCannotBeWrittenAreRefusedAtTheirLine) {
    MapText m = pixel_map();
    m.vertices[2].name = "b\\n(:goal"; // YAML's escape: a newline
    std::string e = error_of(m.yaml());
    EXPECT_NE(e.find("site.building.yaml:7:"), std::string::npos) << e;
    EXPECT_NE(e.find("error: the name of vertex 2 holds a control character (byte 1)"),
              std::string::npos)
        << e;
    m.vertices[2].name = "b\xff";
    EXPECT_NE(error_of(m.yaml()).find("the name of vertex 2 is not UTF-8 text (byte 1)"),
              std::string::npos)
        << error_of(m.yaml());
    m.vertices[2].name = std::string(257, 'b');
    EXPECT_NE(error_of(m.yaml()).find("the name of vertex 2 is longer than 256 bytes"),
              std::string::npos);
    // Only places are written: vertex 3 is on no lane.
    m.vertices[2].name = "caf\xc3\xa9 \xe2\x98\x95";
    m.vertices[3].name = "far\\x01"; // YAML's escape
    EXPECT_EQ(read(m).places[2].name, "caf\xc3\xa9 \xe2\x98\x95");
    m.vertices[3].name = "far";
    m.level = "\"L1\\nalpha: 7\"";
    EXPECT_NE(error_of(m.yaml()).find("error: the level's name holds a control character"),
              std::string::npos)
        << error_of(m.yaml());
}

TEST(BuildingMap, AnEmptyFileIsNoMap) {
    EXPECT_NE(error_of("").find("site.building.yaml:1:1: error: a building map is a YAML map"),
              std::string::npos);
}

TEST(BuildingMap, MoreThanMaxPlacesIsRefused) {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    for (int i = 0; i <= static_cast<int>(MAX_PLACES); ++i)
        m.vertices.push_back({double(i % 100), double(i / 100), ""});
    for (int i = 0; i + 1 < static_cast<int>(m.vertices.size()); i += 2)
        m.lanes.push_back({i, i + 1, true});
    m.lanes.push_back({static_cast<int>(MAX_PLACES) - 1, static_cast<int>(MAX_PLACES), true});
    EXPECT_NE(error_of(m.yaml()).find("10001 places, more than the 10000 a floor may have"),
              std::string::npos);
}

} // namespace
} // namespace envdesign::floor
