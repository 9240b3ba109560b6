// The one picture of a floor (floor_draw.h) on a floor.json the test writes: a 10 m x 5 m
// floor, 100 px a metre at width_px 1000, so every pixel below is known.

#include "floor/floor_draw.h"
#include "floor/floor_error.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

using nlohmann::json;

// v0 (0, 0) dock, v1 (10, 0), v2 (10, 5) shelf, v3 (0, 5) off the graph's paths; lanes
// v0 -> v1 -> v2, people see v0 -> v2; one wall from (5, 1) to (5, 5); a tape on v0-v2.
json small_floor() {
    return json::parse(R"({
      "format": "envdesign-floor", "source": {"map": "test <map>"},
      "places": [{"object": "v0", "vertex": 0, "name": "dock", "x": 0, "y": 0},
                 {"object": "v1", "vertex": 1, "name": "", "x": 10, "y": 0},
                 {"object": "v2", "vertex": 2, "name": "shelf", "x": 10, "y": 5},
                 {"object": "v3", "vertex": 3, "name": "", "x": 0, "y": 5}],
      "robot_edges": [["v0", "v1"], ["v1", "v2"]],
      "human_only_edges": [["v0", "v2"]],
      "walls": [[[5, 1], [5, 5]]],
      "candidates": [{"name": "tape-v0-v2", "kind": "tape", "cost": 11.18,
                      "segments": [[[0, 0], [10, 5]]]}]})");
}

std::size_t count(const std::string &text, const std::string &what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

TEST(FloorDraw, PlanPlacesFollowsTheMoves) {
    EXPECT_EQ(plan_places({"(move v1 v3)", "(move v3 v4)"}),
              (std::vector<std::string>{"v1", "v3", "v4"}));
    EXPECT_EQ(plan_places({"(wait v1)", "(move v1 v3)"}), (std::vector<std::string>{"v1", "v3"}));
    EXPECT_TRUE(plan_places({}).empty());
}

TEST(FloorDraw, DrawsMetresAsPixelsNorthUp) {
    FloorDrawing d;
    std::string svg = floor_svg(small_floor(), d);
    // 10 m across -> 1000 px, a 20 px margin; y flipped: y 5 m is the top (20 px).
    EXPECT_NE(svg.find("<line x1=\"20\" y1=\"520\" x2=\"1020\" y2=\"520\" class=\"robot-edge\""),
              std::string::npos)
        << svg;
    EXPECT_NE(svg.find("<line x1=\"520\" y1=\"420\" x2=\"520\" y2=\"20\" class=\"wall\""),
              std::string::npos);
    EXPECT_NE(svg.find("viewBox=\"0 0 1120 560\""), std::string::npos); // +100 px for labels
    EXPECT_EQ(count(svg, "class=\"robot-edge\""), 2u);
    EXPECT_EQ(count(svg, "class=\"human-edge\""), 1u);
    EXPECT_EQ(count(svg, "class=\"tape\""), 0u); // not chosen
    EXPECT_NE(svg.find("<title>test &lt;map&gt;</title>"), std::string::npos);
    EXPECT_NE(svg.find(">v0 dock</text>"), std::string::npos);
    EXPECT_NE(svg.find(">v1</text>"), std::string::npos);
    EXPECT_NE(svg.find(">v3</text>"), std::string::npos);
    EXPECT_EQ(count(svg, "<circle class=\"place\""), 4u);
}

TEST(FloorDraw, DrawsPathsAndLabelsOnlyTheirPlacesWhenAsked) {
    FloorDrawing d;
    d.design = {"tape-v0-v2"};
    d.paths.push_back({plan_places({"(move v0 v1)", "(move v1 v2)"}), PathStyle::ROBOT, "r"});
    d.paths.push_back({{"v0", "v2"}, PathStyle::EXPECTED, "e"});
    d.label_path_places_only = true;
    d.legend = false;
    std::string svg = floor_svg(small_floor(), d);
    EXPECT_NE(svg.find("<g class=\"robot-path\"><title>r</title><polyline points=\"20,520 "
                       "1020,520 1020,20 \""),
              std::string::npos)
        << svg;
    EXPECT_NE(svg.find("<g class=\"expected-path\"><title>e</title><polyline points=\"20,520 "
                       "1020,20 \""),
              std::string::npos);
    // The robot's path is drawn under the expected one.
    EXPECT_LT(svg.find("robot-path"), svg.find("expected-path"));
    EXPECT_EQ(count(svg, "class=\"tape\""), 1u);
    EXPECT_NE(svg.find(">v0 dock</text>"), std::string::npos);
    EXPECT_NE(svg.find(">v2 shelf</text>"), std::string::npos);
    EXPECT_NE(svg.find(">v1</text>"), std::string::npos); // on the robot's path
    EXPECT_EQ(svg.find(">v3</text>"), std::string::npos); // on no path
    EXPECT_EQ(svg.find("grey: lanes"), std::string::npos);
}

TEST(FloorDraw, RefusesWhatItCannotDraw) {
    FloorDrawing d;
    d.paths.push_back({{"v0", "v9"}, PathStyle::ROBOT, ""});
    EXPECT_THROW(floor_svg(small_floor(), d), FloorError);
    json broken = small_floor();
    broken["places"][1].erase("x");
    EXPECT_THROW(floor_svg(broken, {}), FloorError);
    json unknown = small_floor();
    unknown["robot_edges"].push_back({"v0", "v7"});
    EXPECT_THROW(floor_svg(unknown, {}), FloorError);
}

} // namespace
} // namespace envdesign::floor
