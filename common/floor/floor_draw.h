#pragma once
// The one picture of a floor: floor.json (floor_json.h) as SVG, north up. Walls black, lanes
// grey, what people expect and the lanes do not offer dashed blue, places as dots with their
// object and name, the chosen candidates (tapes orange, new lanes green, BLOCKED zones red,
// LINE_GUIDED zones yellow), and paths over the places (a task's plans). `envdesign floor
// draw` writes it to a file; `envdesign report` puts it in its page.
//
//   nlohmann::json floor = read_floor_json("imported/");
//   FloorDrawing d;
//   d.design = {"gap-barrier"};
//   d.paths.push_back({plan_places(plan), PathStyle::ROBOT, "the robot"});
//   std::string svg = floor_svg(floor, d);
//
// Every element has a class for what it shows (wall, robot-edge, human-edge, place, tape,
// lane, zone, robot-path, expected-path), so that a page's script or a test can find it.

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace envdesign::floor {

enum class PathStyle {
    ROBOT,    // what the robot does: a wide purple line
    EXPECTED, // what people expect: a dashed dark blue line on top
};

struct DrawnPath {
    std::vector<std::string> places; // objects ("v19"), in the order visited
    PathStyle style = PathStyle::ROBOT;
    std::string title; // shown on hover
};

struct FloorDrawing {
    std::set<std::string> design; // the candidates drawn (names in floor.json)
    std::vector<DrawnPath> paths;
    double width_px = 1000; // of the floor's longer side
    // Label only the places on a path (a small picture of one task); else every place.
    bool label_path_places_only = false;
    bool legend = true;
};

// DIR/floor.json, checked to be one `floor import` wrote. Throws pddl::ParseError at
// FILE:LINE:COL when it does not read or is not one.
nlohmann::json read_floor_json(const std::string &dir);

// The SVG document (an <svg> element, no XML prolog: it may sit inside HTML). Throws
// FloorError when floor.json lacks what the picture needs, or a path names no place.
std::string floor_svg(const nlohmann::json &floor, const FloorDrawing &drawing);

// The places a plan of the floor's domain visits: "(move v1 v3)", "(move v3 v4)" -> v1, v3,
// v4. Steps of other actions are skipped; an empty plan visits nothing.
std::vector<std::string> plan_places(const std::vector<std::string> &plan);

} // namespace envdesign::floor
