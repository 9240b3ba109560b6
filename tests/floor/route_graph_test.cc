// Nav2 route graphs (GeoJSON nodes and directed edges, cost where given) and occupancy maps
// (map_server's map.yaml + PGM, trinary), whose occupied cells block sight lines.

#include "floor/floor_graph.h"
#include "floor/occupancy_map.h"
#include "floor/route_graph.h"

#include "map_text.h"

#include "pddl/parse_error.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

std::string node(int id, double x, double y, const std::string &extra = "") {
    return R"({"type": "Feature", "geometry": {"type": "Point", "coordinates": [)" +
           std::to_string(x) + ", " + std::to_string(y) + R"(]}, "properties": {"id": )" +
           std::to_string(id) + extra + "}}";
}

std::string edge(int id, int from, int to, const std::string &extra = "") {
    return R"({"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": )" +
           std::to_string(id) + ", \"startid\": " + std::to_string(from) +
           ", \"endid\": " + std::to_string(to) + extra + "}}";
}

std::string graph(const std::vector<std::string> &features) {
    std::string out = "{\"type\": \"FeatureCollection\", \"features\": [\n";
    for (std::size_t i = 0; i < features.size(); ++i)
        out += features[i] + (i + 1 < features.size() ? ",\n" : "\n");
    return out + "]}\n";
}

// dock (0,0) -> v1 (5,0) <-> shelf (5,5); node 3 is on no edge; 2 -> 2 is ignored.
std::string three_nodes() {
    return graph({node(0, 0, 0, ", \"name\": \"dock\""), node(1, 5, 0),
                  node(2, 5, 5, ", \"metadata\": {\"name\": \"shelf\"}"), node(3, 9, 9),
                  edge(10, 0, 1, ", \"cost\": 7.5"), edge(11, 1, 2), edge(12, 2, 1),
                  edge(13, 2, 2)});
}

std::string graph_error_of(const std::string &text) {
    try {
        parse_route_graph(text, "route.geojson");
    } catch (const pddl::ParseError &e) {
        return e.what();
    }
    return "no error";
}

TEST(RouteGraph, NodesOnEdgesArePlacesAndEdgesAreDirected) {
    Floor f = parse_route_graph(three_nodes(), "route.geojson");
    ASSERT_EQ(f.places.size(), 3u);
    EXPECT_EQ(f.places[0].name, "dock");
    EXPECT_EQ(f.places[2].name, "shelf");
    EXPECT_DOUBLE_EQ(f.places[2].at.y, 5);
    std::vector<Edge> lanes{{0, 1}, {1, 2}, {2, 1}};
    EXPECT_EQ(f.lanes, lanes);
}

TEST(RouteGraph, AGivenCostIsTheEdgesLengthInMetres) {
    Floor f = parse_route_graph(three_nodes(), "route.geojson");
    FloorGraph g = build_floor_graph(f, 10);
    EXPECT_EQ(edge_length_dm(f, g, {0, 1}), 75); // cost 7.5 m, though 5 m apart
    EXPECT_EQ(edge_length_dm(f, g, {1, 2}), 50); // no cost: the segment
    EXPECT_EQ(edge_length_dm(f, g, {1, 0}), 50); // a sight line: the segment
    std::vector<Edge> human_only{{0, 2}, {1, 0}, {2, 0}};
    EXPECT_EQ(g.human_only, human_only);
}

TEST(RouteGraph, FaultsAreAtTheirLine) {
    EXPECT_NE(
        graph_error_of("{\"features\": [\n  {]}").find("route.geojson:2:4: error: malformed JSON"),
        std::string::npos)
        << graph_error_of("{\"features\": [\n  {]}");
    std::string twice = graph({node(0, 0, 0), node(0, 1, 0), edge(5, 0, 0)});
    EXPECT_NE(graph_error_of(twice).find("route.geojson:3:"), std::string::npos)
        << graph_error_of(twice);
    EXPECT_NE(graph_error_of(twice).find("node id 0 is given twice"), std::string::npos);
    std::string unknown = graph({node(0, 0, 0), node(1, 1, 0), edge(5, 0, 7)});
    EXPECT_NE(graph_error_of(unknown).find("route.geojson:4:"), std::string::npos)
        << graph_error_of(unknown);
    EXPECT_NE(graph_error_of(unknown).find("edge 2 names node 7, which is not in the graph"),
              std::string::npos);
    std::string no_id = graph(
        {node(0, 0, 0),
         R"({"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 1]}, "properties": {"id": "a"}})"});
    EXPECT_NE(graph_error_of(no_id).find("node 1's id is not an integer id >= 0"),
              std::string::npos);
    std::string degrees = "{\"crs\": {\"type\": \"name\", \"properties\": {\"name\": "
                          "\"urn:ogc:def:crs:EPSG::4326\"}}, \"features\": []}";
    EXPECT_NE(graph_error_of(degrees).find("is not supported: a route graph must be in metres"),
              std::string::npos);
    std::string huge = graph({node(0, 0, 0), node(1, 2e6, 0), edge(5, 0, 1)});
    EXPECT_NE(graph_error_of(huge).find("x is not a finite number within 1e6"), std::string::npos);
    EXPECT_NE(graph_error_of(graph({node(0, 0, 0)})).find("no edge between two nodes"),
              std::string::npos);
    // Found by mutating the example: a number beyond a double, coordinates that are no list.
    EXPECT_NE(graph_error_of("{\"features\": [1e400]}")
                  .find("route.geojson:1:1: error: malformed "
                        "JSON: number overflow"),
              std::string::npos)
        << graph_error_of("{\"features\": [1e400]}");
    std::string flat =
        R"({"features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": 5}, "properties": {"id": 1}}]})";
    EXPECT_NE(graph_error_of(flat).find("error: node 1 has no coordinates [x, y]"),
              std::string::npos)
        << graph_error_of(flat);
}

// Issue 21 (fuzz_floor_inputs): a label is written into comments and floor.json.
TEST(RouteGraph, ALabelThatCannotBeWrittenIsRefused) {
    std::string text =
        graph({node(0, 0, 0, ", \"name\": \"dock\\n(:goal\""), node(1, 5, 0), edge(10, 0, 1)});
    EXPECT_NE(graph_error_of(text).find("route.geojson:2:"), std::string::npos)
        << graph_error_of(text);
    EXPECT_NE(graph_error_of(text).find("error: the name of node 0 holds a control character"),
              std::string::npos)
        << graph_error_of(text);
}

// Issue 21, found by fuzz_floor_inputs: a Point whose geometry has no `coordinates` key was
// looked up with a const json's operator[], which asserts (undefined without asserts).
TEST(RouteGraph, APointWithoutCoordinatesIsAnErrorNotACrash) {
    std::string text = graph(
        {node(0, 0, 0),
         R"({"type": "Feature", "geometry": {"type": "Point", "coordi&nates": [2, 8]}, "properties": {"id": 21}})",
         edge(10, 0, 21)});
    EXPECT_NE(graph_error_of(text).find("route.geojson:3:"), std::string::npos)
        << graph_error_of(text);
    EXPECT_NE(graph_error_of(text).find("error: node 21 has no coordinates [x, y]"),
              std::string::npos)
        << graph_error_of(text);
}

TEST(Pgm, BinaryAndPlainAreReadAndScaledTo255) {
    GreyImage plain = parse_pgm("P2\n# a comment\n3 1\n15\n0 15 8\n", "m.pgm");
    ASSERT_EQ(plain.width, 3);
    EXPECT_EQ(plain.grey, (std::vector<std::uint8_t>{0, 255, 136}));
    std::string binary = "P5 2 1 255\n";
    binary += '\x00';
    binary += '\xfe';
    EXPECT_EQ(parse_pgm(binary, "m.pgm").grey, (std::vector<std::uint8_t>{0, 254}));
    EXPECT_THROW(parse_pgm("P5 2 1 255\n\x01", "m.pgm"), pddl::ParseError); // short raster
    EXPECT_THROW(parse_pgm("\x89PNG....", "m.png"), pddl::ParseError);
}

// A 10 x 10 map of 1 m cells at origin (0, 0): black (occupied) column x = 4, rows 2..7
// (y up), grey (unknown) cell (7, 5), the rest white (free).
std::filesystem::path write_map(const std::string &name, const std::string &extra = "") {
    auto dir = testing::scratch_dir(name);
    std::string pgm = "P2\n10 10\n255\n";
    for (int row_from_top = 0; row_from_top < 10; ++row_from_top)
        for (int col = 0; col < 10; ++col) {
            int y = 9 - row_from_top;
            bool wall = col == 4 && y >= 2 && y <= 7;
            bool unknown = col == 7 && y == 5;
            pgm += std::string(wall ? "0" : unknown ? "205" : "254") + (col == 9 ? "\n" : " ");
        }
    testing::write_text(dir / "map.pgm", pgm);
    testing::write_text(dir / "map.yaml", "image: map.pgm\nresolution: 1.0\norigin: [0.0, 0.0, 0]\n"
                                          "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" +
                                              extra);
    return dir / "map.yaml";
}

TEST(OccupancyMap, OccupiedCellsBlockFreeAndUnknownOnesDoNot) {
    OccupancyGrid grid = read_occupancy_map(write_map("grid").string());
    EXPECT_TRUE(grid.occupied_at(4, 5));
    EXPECT_FALSE(grid.occupied_at(7, 5));                // unknown: p = 0.196, not above 0.65
    EXPECT_TRUE(grid.blocks({{1.5, 5.5}, {8.5, 5.5}}));  // across the black column
    EXPECT_FALSE(grid.blocks({{1.5, 8.5}, {8.5, 8.5}})); // above it
    EXPECT_FALSE(grid.blocks({{6.5, 5.5}, {8.5, 5.5}})); // through the unknown cell
    EXPECT_FALSE(grid.blocks({{4.5, 5.5}, {8.5, 5.5}})); // from inside the black cell
    EXPECT_FALSE(grid.blocks({{-20, 5.5}, {-10, 5.5}})); // off the map
    EXPECT_TRUE(grid.blocks({{-20, 5.5}, {20, 5.5}}));   // through the map from outside
}

TEST(OccupancyMap, NegateInvertsAndOtherModesOrRotationsAreRefused) {
    OccupancyGrid grid = read_occupancy_map(write_map("negate").string());
    auto negated = write_map("negated");
    std::string yaml = testing::read_text(negated);
    testing::write_text(negated, yaml.replace(yaml.find("negate: 0"), 9, "negate: 1"));
    OccupancyGrid n = read_occupancy_map(negated.string());
    EXPECT_FALSE(n.occupied_at(4, 5)); // black is now free
    EXPECT_TRUE(n.occupied_at(0, 0));  // and white occupied
    EXPECT_TRUE(grid.occupied_at(4, 5));
    auto scale = write_map("scale", "mode: scale\n");
    EXPECT_THROW(read_occupancy_map(scale.string()), pddl::ParseError);
    auto rotated = write_map("rotated");
    yaml = testing::read_text(rotated);
    testing::write_text(rotated, yaml.replace(yaml.find("0.0, 0]"), 7, "0.0, 0.5]"));
    try {
        read_occupancy_map(rotated.string());
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        EXPECT_NE(std::string(e.what()).find(":3:9: error: a rotated map"), std::string::npos)
            << e.what();
    }
}

TEST(OccupancyMap, BlocksSightLinesOfARouteGraph) {
    // Two nodes either side of the black column, 7 m apart, joined only around it.
    std::string text = graph({node(0, 1.5, 5.5, ", \"name\": \"a\""), node(1, 1.5, 9.5),
                              node(2, 8.5, 9.5), node(3, 8.5, 5.5, ", \"name\": \"b\""),
                              edge(10, 0, 1), edge(11, 1, 2), edge(12, 2, 3)});
    Floor f = parse_route_graph(text, "route.geojson");
    FloorGraph open = build_floor_graph(f, 10);
    EXPECT_EQ(std::count(open.human_only.begin(), open.human_only.end(), Edge{0, 3}), 1);
    f.occupancy = std::make_shared<OccupancyGrid>(read_occupancy_map(write_map("sight").string()));
    FloorGraph walled = build_floor_graph(f, 10);
    EXPECT_EQ(std::count(walled.human_only.begin(), walled.human_only.end(), Edge{0, 3}), 0);
    EXPECT_EQ(std::count(walled.human_only.begin(), walled.human_only.end(), Edge{1, 0}), 1);
}

} // namespace
} // namespace envdesign::floor
