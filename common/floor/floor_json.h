#pragma once
// floor.json: the geometry of an imported floor, beside its design problem, for drawing
// and for export back to the site. Everything in metres, y up (docs/floors.md "floor.json"):
//   {"format": "envdesign-floor", "version": 1,
//    "source": {"map" (absolute path), "format": "building_map"|"route_graph", "level",
//               "graph", "metres_per_unit", "occupancy_map" (--map, absolute)}, "sight_m",
//    "places": [{"object": "v3", "vertex": 3, "name": "pantry", "x", "y"}],
//    "robot_edges": [["v1", "v3"], ...], "human_only_edges": [...],
//    "walls": [[[x, y], [x, y]], ...],
//    "tasks": [{"name": "v1-v3", "from": "v1", "to": "v3", "probability"}],
//    "candidates": [{"name", "kind": "tape"|"lane"|"zone", "cost",
//                    "segments": [[[x, y], [x, y]], ...], "edges": [["v1", "v3"], ...] (the
//                    atoms its edits add or remove), "zone_type", "polygon"}]}

#include "floor_problem.h"

#include <nlohmann/json.hpp>

namespace envdesign::floor {

nlohmann::json floor_json(const FloorProblem &problem);

} // namespace envdesign::floor
