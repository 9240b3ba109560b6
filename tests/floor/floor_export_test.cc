// `floor export`: a design back in the site's formats. The map copy re-imports with the new
// lanes as robot edges (round trip), the GeoJSON is GeoJSON of the chosen candidates, the
// keepout mask has the map's size, resolution and origin.

#include "floor/building_map.h"
#include "floor/floor_error.h"
#include "floor/floor_export.h"
#include "floor/floor_graph.h"
#include "floor/floor_import.h"
#include "floor/occupancy_map.h"
#include "floor/route_graph.h"

#include "../cli/run_command.h"
#include "map_text.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace envdesign::floor {
namespace {

namespace fs = std::filesystem;
using testing::MapText;

// The L of floor_cli_test in metres: dock (0,0) - v1 (0,4) - shelf (4,4), and a one-way
// lane shelf -> v3 (8,4) whose reverse people expect.
MapText l_shape_in_metres() {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, "dock"}, {0, 4, ""}, {4, 4, "shelf"}, {8, 4, "pack"}};
    m.lanes = {{0, 1, true}, {1, 2, true}, {2, 3, false}};
    return m;
}

fs::path imported(const std::string &name, const MapText &m, const std::string &zones = "") {
    fs::path dir = testing::scratch_dir(name);
    ImportOptions o;
    o.map = testing::write_text(dir / "l.building.yaml", m.yaml());
    o.out_dir = (dir / "in").string();
    if (!zones.empty())
        o.zones_json = testing::write_text(dir / "zones.json", zones);
    import_floor(o);
    return dir;
}

const char *BARRIER = R"({"zones": [{"zoneId": "barrier", "zoneType": "BLOCKED", "cost": 1,
  "vertices": [{"x": 1.5, "y": 1.5}, {"x": 2.5, "y": 1.5}, {"x": 2.5, "y": 2.5}, {"x": 1.5, "y": 2.5}]}]})";

TEST(FloorExport, TheMapCopyReimportsWithTheNewLanesAsRobotEdges) {
    fs::path dir = imported("export-rmf", l_shape_in_metres());
    ExportReport r = export_design(
        {(dir / "in").string(), {"lane-v0-v2", "lane-v2-v3"}, (dir / "out").string()});
    ASSERT_EQ(r.written.size(), 2u);
    Floor again = read_building_map((dir / "out/l.building.yaml").string(), {});
    // v0-v2 both ways (a two-way lane), v3 -> v2 (one way, the other was a lane already).
    for (Edge e : {Edge{0, 2}, Edge{2, 0}, Edge{3, 2}})
        EXPECT_EQ(std::count(again.lanes.begin(), again.lanes.end(), e), 1)
            << e.from << "->" << e.to;
    EXPECT_EQ(again.lanes.size(), 8u);
    // People's straight lines there are now lanes: no longer human-only.
    std::vector<Edge> human_only = build_floor_graph(again, 10).human_only;
    for (Edge e : {Edge{0, 2}, Edge{2, 0}, Edge{3, 2}})
        EXPECT_EQ(std::count(human_only.begin(), human_only.end(), e), 0);
    std::string yaml = testing::read_text(dir / "out/l.building.yaml");
    EXPECT_NE(yaml.find("[0, 2, {bidirectional: [4, true], graph_idx: [2, 0]"), std::string::npos)
        << yaml;
    EXPECT_NE(yaml.find("[3, 2, {bidirectional: [4, false]"), std::string::npos);
}

TEST(FloorExport, TheGeoJsonHasEveryChosenCandidateInMetres) {
    fs::path dir = imported("export-geojson", l_shape_in_metres(), BARRIER);
    export_design({(dir / "in").string(), {"tape-v0-v2", "barrier"}, (dir / "out").string()});
    auto doc = nlohmann::json::parse(testing::read_text(dir / "out/design.geojson"));
    EXPECT_EQ(doc["type"], "FeatureCollection");
    ASSERT_EQ(doc["features"].size(), 2u);
    const auto &tape = doc["features"][0];
    EXPECT_EQ(tape["geometry"]["type"], "LineString");
    EXPECT_EQ(tape["geometry"]["coordinates"], nlohmann::json::parse("[[0.0, 0.0], [4.0, 4.0]]"));
    EXPECT_EQ(tape["properties"]["name"], "tape-v0-v2");
    EXPECT_DOUBLE_EQ(tape["properties"]["cost"].get<double>(), 5.66);
    const auto &zone = doc["features"][1];
    EXPECT_EQ(zone["geometry"]["type"], "Polygon");
    const auto &ring = zone["geometry"]["coordinates"][0];
    EXPECT_EQ(ring.size(), 5u);
    EXPECT_EQ(ring.front(), ring.back()); // closed, as GeoJSON wants
    EXPECT_EQ(zone["properties"]["zone_type"], "BLOCKED");
}

TEST(FloorExport, UnknownNamesAndExportingOntoTheMapAreRefused) {
    fs::path dir = imported("export-bad", l_shape_in_metres());
    EXPECT_THROW(export_design({(dir / "in").string(), {"tape-v9-v10"}, (dir / "out").string()}),
                 FloorError);
    EXPECT_THROW(export_design({(dir / "in").string(), {"tape-v0-v2"}, dir.string()}), FloorError);
    auto r = envdesign::testing::run_envdesign("floor export " + (dir / "in").string() +
                                               " --design nope -o " + (dir / "o").string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.out.find("no candidate 'nope'"), std::string::npos) << r.out;
}

TEST(FloorExport, ARouteGraphGetsNewEdgesAndABarrierAKeepoutMask) {
    fs::path dir = testing::scratch_dir("export-nav2");
    std::string route = testing::write_text(dir / "route.geojson", R"({"features": [
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0.5, 0.5]}, "properties": {"id": 0, "name": "a"}},
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0.5, 3.5]}, "properties": {"id": 1}},
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [3.5, 3.5]}, "properties": {"id": 7, "name": "b"}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 2, "startid": 0, "endid": 1}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 3, "startid": 1, "endid": 7}}]})");
    std::string pgm = "P2\n4 4\n255\n";
    for (int i = 0; i < 16; ++i)
        pgm += "254\n";
    testing::write_text(dir / "map.pgm", pgm);
    std::string map = testing::write_text(dir / "map.yaml", "image: map.pgm\nresolution: 1\n"
                                                            "origin: [0, 0, 0]\n");
    std::string zones = testing::write_text(dir / "zones.json", BARRIER);
    ImportOptions o;
    o.map = route;
    o.occupancy_yaml = map;
    o.zones_json = zones;
    o.out_dir = (dir / "in").string();
    import_floor(o);
    ExportReport r = export_design({o.out_dir, {"lane-v0-v7", "barrier"}, (dir / "out").string()});
    ASSERT_EQ(r.written.size(), 4u); // design.geojson, route.geojson, keepout.pgm, keepout.yaml
    Floor again = read_route_graph((dir / "out/route.geojson").string());
    for (Edge e : {Edge{0, 7}, Edge{7, 0}})
        EXPECT_EQ(std::count(again.lanes.begin(), again.lanes.end(), e), 1);
    auto graph = nlohmann::json::parse(testing::read_text(dir / "out/route.geojson"));
    EXPECT_EQ(graph["features"][5]["properties"]["id"], 8); // after the largest id, 7
    OccupancyGrid mask = read_occupancy_map((dir / "out/keepout.yaml").string());
    EXPECT_EQ(mask.width, 4);
    EXPECT_EQ(mask.height, 4);
    EXPECT_DOUBLE_EQ(mask.resolution, 1);
    EXPECT_DOUBLE_EQ(mask.origin.x, 0);
    // The barrier (1.5..2.5)^2 holds the centres of cells (1,1), (2,1), (1,2), (2,2).
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            EXPECT_EQ(mask.occupied_at(col, row), col >= 1 && col <= 2 && row >= 1 && row <= 2)
                << col << "," << row;
}

} // namespace
} // namespace envdesign::floor
