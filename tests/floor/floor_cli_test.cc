// `envdesign floor import` as a user runs it: the real binary on maps the test writes, then
// `envdesign design` on what it wrote; and its bad input, exit code 2 with FILE:LINE:COL.

#include "../cli/run_command.h"
#include "map_text.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace envdesign::floor {
namespace {

using envdesign::testing::run_envdesign;
using testing::MapText;
namespace fs = std::filesystem;

// An L in pixels (0.05 m a pixel): dock (0,0) -> v1 (0,-80 px = 4 m up) -> shelf (4 m, 4 m).
// The robot drives 8 m; people expect the 5.66 m diagonal.
MapText l_shape() {
    MapText m;
    m.vertices = {{0, 0, "dock"}, {0, -80, ""}, {80, -80, "shelf"}, {200, 0, ""}};
    m.lanes = {{0, 1, true}, {1, 2, true}};
    m.measurements = {{0, 3, 10.0}};
    return m;
}

nlohmann::json design_json(const std::string &spec, const std::string &flags = "") {
    auto r = run_envdesign("design " + spec + " --json " + flags, false);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return nlohmann::json::parse(r.out);
}

TEST(FloorCli, ImportThenDesignChoosesTheTapeThatMakesTheRobotExplicable) {
    fs::path dir = testing::scratch_dir("l-shape");
    std::string map = testing::write_text(dir / "l.building.yaml", l_shape().yaml());
    auto r = run_envdesign("floor import " + map + " -o " + (dir / "out").string());
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("3 places, 4 robot edges, 2 human-only edges, 2 tasks, 2 candidates"),
              std::string::npos)
        << r.out;
    std::string spec = testing::read_text(dir / "out/design.textproto");
    EXPECT_NE(spec.find("task { name: \"v0-v2\" problem: \"tasks/v0-v2.pddl\" human_problem: "
                        "\"tasks/v0-v2-human.pddl\" }"),
              std::string::npos)
        << spec;
    EXPECT_NE(spec.find("modification {\n  name: \"tape-v0-v2\" cost: 5.66\n  edit { model: HUMAN "
                        "remove_init: \"(connected v0 v2)\" }\n  edit { model: HUMAN remove_init: "
                        "\"(connected v2 v0)\" }\n}"),
              std::string::npos);
    EXPECT_NE(spec.find("name: \"lane-v0-v2\" cost: 56.57"), std::string::npos);
    EXPECT_NE(spec.find("alpha: 1 beta: 1 kappa: 0 gamma: 1 horizon: 1\ndistance: COST_DIFF"),
              std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "out/floor.json"));
    auto result = design_json((dir / "out/design.textproto").string());
    // IE = 80 dm along the lanes - 57 dm straight, each way; the tape (5.66) removes it.
    EXPECT_EQ(result["design"], nlohmann::json::array({"tape-v0-v2"}));
    EXPECT_DOUBLE_EQ(result["objective"].get<double>(), 5.66);
    EXPECT_DOUBLE_EQ(result["baseline"]["objective"].get<double>(), 23);
}

// A small site: two aisles with a rack (walls) between, named stations, a one-way lane,
// a zone file: tape, lane and zone candidates together.
MapText small_site() {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, "in"}, {0, 6, ""}, {6, 6, "pick"},  {6, 0, "out"},
                  {3, 4.5, ""}, {3, 7, ""}, {9, 3, "charge"}};
    m.lanes = {{0, 1, true}, {1, 2, true}, {2, 3, false}, {3, 0, true}, {2, 6, true}, {6, 3, true}};
    m.walls = {{4, 5}}; // a rack from the north wall into the square
    return m;
}

const char *SITE_ZONES = R"({"zones": [
 {"zoneId": "close-gap", "zoneType": "BLOCKED", "cost": 4,
  "vertices": [{"x": 2.5, "y": 5.5}, {"x": 3.5, "y": 5.5}, {"x": 3.5, "y": 6.5}, {"x": 2.5, "y": 6.5}]},
 {"zoneId": "mark-east", "zoneType": "LINE_GUIDED", "cost": 1.5,
  "vertices": [{"x": 5.5, "y": 0.5}, {"x": 9.5, "y": 0.5}, {"x": 9.5, "y": 5.5}, {"x": 5.5, "y": 5.5}]}
]})";

TEST(FloorCli, TheWrittenSpecGivesTheDesignAnExhaustiveSearchFinds) {
    fs::path dir = testing::scratch_dir("site");
    std::string map = testing::write_text(dir / "site.building.yaml", small_site().yaml());
    std::string zones = testing::write_text(dir / "zones.json", SITE_ZONES);
    auto r = run_envdesign("floor import " + map + " -o " + (dir / "out").string() + " --zones " +
                           zones +
                           " --sight 9 --tape-cost 2 --beta 0.5 --horizon 3"
                           " --gamma 0.9 --kappa 0.01");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    std::string spec = (dir / "out/design.textproto").string();
    auto witness = design_json(spec);
    auto exhaustive = design_json(spec, "--search exhaustive");
    EXPECT_EQ(witness["design"], exhaustive["design"]);
    EXPECT_NEAR(witness["objective"].get<double>(), exhaustive["objective"].get<double>(), 1e-9);
    EXPECT_GT(witness["baseline"]["objective"].get<double>(), witness["objective"].get<double>());
    // Three pairs (in-pick, v1-out across the open square, out->pick against the one-way
    // lane) with a tape and a lane each, and both zones: 2^8 designs.
    EXPECT_NE(r.out.find("5 human-only edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("8 candidates"), std::string::npos) << r.out;
}

// A zigzag aisle of eight named stations: the robot drives every zig, people see the 2 m
// straight line past each corner (sight 2.1 m), so six tapes, and 56 tasks whose routes
// share those lines: each tape crosses the expected routes of many tasks, where the witness
// search's probes plan only their own task (witness_learning.cc, probe). 2^6 designs.
TEST(FloorCli, AZigzagAisleOfManyTasksGivesTheDesignAnExhaustiveSearchFinds) {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({double(i), double(i % 2), "s" + std::to_string(i)});
    for (int i = 0; i + 1 < 8; ++i)
        m.lanes.push_back({i, i + 1, true});
    fs::path dir = testing::scratch_dir("zigzag");
    std::string map = testing::write_text(dir / "zigzag.building.yaml", m.yaml());
    auto r = run_envdesign("floor import " + map + " -o " + (dir / "out").string() +
                           " --sight 2.1 --candidates tape --tape-cost 0.8");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("8 places, 14 robot edges, 12 human-only edges, 56 tasks, 6 candidates"),
              std::string::npos)
        << r.out;
    std::string spec = (dir / "out/design.textproto").string();
    auto witness = design_json(spec);
    auto exhaustive = design_json(spec, "--search exhaustive");
    EXPECT_EQ(witness["design"], exhaustive["design"]);
    EXPECT_NEAR(witness["objective"].get<double>(), exhaustive["objective"].get<double>(), 1e-9);
    EXPECT_EQ(witness["status"], "optimal");
    // The two middle lines, each on many routes, pay for their 1.6 of tape; the outer four
    // do not (0.6, 0.7 give all six; 0.9 none).
    EXPECT_EQ(witness["design"], nlohmann::json::array({"tape-v2-v4", "tape-v3-v5"}));
    EXPECT_NEAR(witness["objective"].get<double>(), 66.4 / 7, 1e-9);
}

std::string run_import(const std::string &name, const std::string &yaml, const std::string &flags,
                       int expected_code) {
    fs::path dir = testing::scratch_dir(name);
    std::string map = testing::write_text(dir / "m.building.yaml", yaml);
    auto r = run_envdesign("floor import " + map + " -o " + (dir / "out").string() + " " + flags);
    EXPECT_EQ(r.exit_code, expected_code) << r.out;
    return r.out;
}

TEST(FloorCli, Wgs84IsRefusedWithExitTwo) {
    MapText m = l_shape();
    m.coordinate_system = "wgs84";
    std::string out = run_import("wgs84", m.yaml(), "", 2);
    EXPECT_NE(out.find("m.building.yaml:1:20: error: coordinate system 'wgs84' is not supported"),
              std::string::npos)
        << out;
}

TEST(FloorCli, BadInputIsExitTwoWithItsPlace) {
    std::string out = run_import("level", l_shape().yaml(), "--level L7", 2);
    EXPECT_NE(out.find("no level 'L7'; the levels are: L1"), std::string::npos) << out;
    out = run_import("graph", l_shape().yaml(), "--graph 3", 2);
    EXPECT_NE(out.find("no lane of graph 3 on this level; its graphs are: 0"), std::string::npos);
    out = run_import("yaml", "levels: {L1: [}\n", "", 2);
    EXPECT_NE(out.find("m.building.yaml:1:"), std::string::npos) << out;
    fs::path dir = testing::scratch_dir("csv-file");
    std::string csv = testing::write_text(dir / "t.csv", "from,to,weight\ndock,office,1\n");
    out = run_import("csv", l_shape().yaml(), "--tasks " + csv, 2);
    EXPECT_NE(out.find(csv + ":2:6: error: no place 'office'"), std::string::npos) << out;
    out = run_import("sight", l_shape().yaml(), "--sight -1", 2);
    EXPECT_NE(out.find("--sight: must be a number in [0, 1e+06] (got -1)"), std::string::npos)
        << out;
    out = run_import("json", l_shape().yaml(), "--json --graph 3", 2);
    EXPECT_NE(out.find("\"exit_code\":2"), std::string::npos) << out;
}

TEST(FloorCli, UnreachableTasksAreDroppedWithAWarning) {
    MapText m = l_shape();
    m.lanes = {{0, 1}, {1, 2}}; // one way: shelf cannot get back to the dock
    std::string out = run_import("oneway", m.yaml(), "", 0);
    EXPECT_NE(out.find("task v2-v0 dropped: the robot's lanes do not lead from v2 (shelf) to v0 "
                       "(dock)"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("1 tasks"), std::string::npos);
}

// A Nav2 route graph: a (0.5, 2.5) -> v1 (0.5, 4.5) -> v2 (4.5, 4.5) -> b (4.5, 2.5), and an
// occupancy map of 1 m cells with an occupied column (x 2..3, y 1..3) between a and b.
const char *ROUTE = R"({"type": "FeatureCollection", "features": [
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0.5, 2.5]}, "properties": {"id": 0, "name": "a"}},
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0.5, 4.5]}, "properties": {"id": 1}},
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [4.5, 4.5]}, "properties": {"id": 2}},
 {"type": "Feature", "geometry": {"type": "Point", "coordinates": [4.5, 2.5]}, "properties": {"id": 3, "name": "b"}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 4, "startid": 0, "endid": 1}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 5, "startid": 1, "endid": 2, "cost": 4}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 6, "startid": 2, "endid": 3}},
 {"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 7, "startid": 3, "endid": 0}}
]})";

TEST(FloorCli, ARouteGraphWithAnOccupancyMapImportsAndDesigns) {
    fs::path dir = testing::scratch_dir("nav2");
    std::string route = testing::write_text(dir / "route.geojson", ROUTE);
    std::string pgm = "P2\n6 6\n255\n";
    for (int top = 0; top < 6; ++top)
        for (int col = 0; col < 6; ++col) {
            int y = 5 - top;
            pgm +=
                std::string(col == 2 && y >= 1 && y <= 2 ? "0" : "254") + (col == 5 ? "\n" : " ");
        }
    testing::write_text(dir / "map.pgm", pgm);
    std::string map = testing::write_text(dir / "map.yaml", "image: map.pgm\nresolution: 1\n"
                                                            "origin: [0, 0, 0]\nnegate: 0\n"
                                                            "occupied_thresh: 0.65\n");
    auto r =
        run_envdesign("floor import " + route + " --map " + map + " -o " + (dir / "out").string());
    ASSERT_EQ(r.exit_code, 0) << r.out;
    // a -> b goes round (2 + 4 + 2 m, the middle edge's cost 4); b -> a is a lane. People
    // see a-v2 and v1-b past the column but not a-b through it; they see v1 -> a, v2 -> v1,
    // b -> v2 against the one-way edges.
    EXPECT_NE(r.out.find("4 places, 4 robot edges, 7 human-only edges, 2 tasks"), std::string::npos)
        << r.out;
    std::string human = testing::read_text(dir / "out/tasks/v0-v3-human.pddl");
    EXPECT_EQ(human.find("(connected v0 v3)"), std::string::npos);
    EXPECT_NE(human.find("(= (length v1 v2) 40)"), std::string::npos);
    auto result = design_json((dir / "out/design.textproto").string());
    EXPECT_EQ(result["status"], "optimal");
    r = run_envdesign("floor import " + route + " -o " + (dir / "open").string());
    EXPECT_NE(r.out.find("4 places, 4 robot edges, 8 human-only edges"), std::string::npos)
        << r.out;
}

TEST(FloorCli, CandidatesChooseTheKindsAndJsonSummarises) {
    fs::path dir = testing::scratch_dir("kinds");
    std::string map = testing::write_text(dir / "l.building.yaml", l_shape().yaml());
    auto r = run_envdesign("floor import " + map + " -o " + (dir / "out").string() +
                               " --candidates lane --json",
                           false);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    auto summary = nlohmann::json::parse(r.out);
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_EQ(summary["candidates"], 1);
    EXPECT_EQ(summary["tasks"], 2);
    std::string spec = testing::read_text(dir / "out/design.textproto");
    EXPECT_EQ(spec.find("tape-"), std::string::npos);
    EXPECT_NE(spec.find("name: \"lane-v0-v2\""), std::string::npos);
    r = run_envdesign("floor import " + map + " -o " + (dir / "x").string() +
                      " --candidates paint");
    EXPECT_EQ(r.exit_code, 2) << r.out;
}

// The example warehouse drawn twice, as a building map (pixels, walls) and as a Nav2 site
// (metres, an occupancy map): the same places, models, candidates and design.
TEST(FloorCli, TheExampleWarehouseGivesOneDesignFromBothReaders) {
    fs::path dir = testing::scratch_dir("examples");
    std::string ex = std::string(ENVDESIGN_EXAMPLES) + "/floor/";
    auto rmf = run_envdesign("floor import " + ex + "warehouse.building.yaml --zones " + ex +
                             "zones.json -o " + (dir / "rmf").string());
    auto nav2 = run_envdesign("floor import " + ex + "nav2/route.geojson --map " + ex +
                              "nav2/map.yaml --zones " + ex + "nav2/zones.json -o " +
                              (dir / "nav2").string());
    ASSERT_EQ(rmf.exit_code, 0) << rmf.out;
    ASSERT_EQ(nav2.exit_code, 0) << nav2.out;
    const std::string counts = "9 places, 18 robot edges, 4 human-only edges, 20 tasks, 8 "
                               "candidates";
    EXPECT_NE(rmf.out.find(counts), std::string::npos) << rmf.out;
    EXPECT_NE(nav2.out.find(counts), std::string::npos) << nav2.out;
    auto body = [](const fs::path &spec) { // without the opening comment naming the map
        std::string text = testing::read_text(spec);
        return text.substr(text.find("robot_domain"));
    };
    EXPECT_EQ(body(dir / "rmf/design.textproto"), body(dir / "nav2/design.textproto"));
    auto a = design_json((dir / "rmf/design.textproto").string());
    auto b = design_json((dir / "nav2/design.textproto").string());
    EXPECT_EQ(a["design"], nlohmann::json::parse(R"(["gap-barrier", "top-aisle-marking"])"));
    EXPECT_EQ(a["design"], b["design"]);
    EXPECT_DOUBLE_EQ(a["objective"].get<double>(), 7.5);
    EXPECT_DOUBLE_EQ(b["objective"].get<double>(), 7.5);
}

TEST(FloorCli, DrawPaintsTheFloorAndTheChosenCandidates) {
    fs::path dir = testing::scratch_dir("draw");
    std::string ex = std::string(ENVDESIGN_EXAMPLES) + "/floor/";
    ASSERT_EQ(run_envdesign("floor import " + ex + "warehouse.building.yaml --zones " + ex +
                            "zones.json -o " + (dir / "in").string())
                  .exit_code,
              0);
    auto r = run_envdesign("floor draw " + (dir / "in").string() +
                           " --design gap-barrier,tape-v22-v24 -o " + (dir / "f.svg").string());
    ASSERT_EQ(r.exit_code, 0) << r.out;
    std::string svg = testing::read_text(dir / "f.svg");
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_NE(svg.find("<polygon class=\"zone\""), std::string::npos);
    EXPECT_NE(svg.find("class=\"tape\""), std::string::npos);
    EXPECT_EQ(svg.find("class=\"lane\""), std::string::npos); // not chosen
    EXPECT_NE(svg.find(">v19 pick_a</text>"), std::string::npos);
    auto count = [&](const std::string &what) {
        std::size_t n = 0;
        for (std::size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1))
            ++n;
        return n;
    };
    EXPECT_EQ(count("<circle"), 9u);          // the places
    EXPECT_EQ(count("stroke=\"#222\""), 16u); // the walls: outer 4, racks 4 + 4 + 4
    r = run_envdesign("floor draw " + (dir / "in").string() + " --design nope -o " +
                      (dir / "g.svg").string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
}

TEST(FloorCli, AnOccupancyMapGoesOnlyWithARouteGraph) {
    fs::path dir = testing::scratch_dir("map-flag");
    std::string out =
        run_import("map-with-rmf", l_shape().yaml(), "--map " + (dir / "m.yaml").string(), 2);
    EXPECT_NE(out.find("--map (an occupancy map) goes with a Nav2 route graph"), std::string::npos)
        << out;
}

} // namespace
} // namespace envdesign::floor
