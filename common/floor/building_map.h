#pragma once
// Reading an Open-RMF building map (`*.building.yaml`, as traffic-editor writes it) into a
// Floor, by FLOORS.md "Reading an Open-RMF building map": one level, one fleet graph, its
// lanes, the level's walls, and coordinates in metres.
//
//   Floor floor = read_building_map("warehouse.building.yaml", {});   // the only level, graph 0
//
// Everything wrong with the file throws pddl::ParseError at FILE:LINE:COL (yaml-cpp's marks):
// malformed YAML, a missing or mistyped key, an unknown level or graph (the message lists the
// ones there), a coordinate system other than reference_image or cartesian_meters, a
// coordinate that is not finite or beyond MAX_COORDINATE_M, more than MAX_PLACES places.

#include "floor.h"

#include <optional>
#include <string>

namespace envdesign::floor {

struct BuildingMapOptions {
    std::optional<std::string> level; // default: the only level
    int graph = 0;                    // the lanes' graph_idx
};

// Reads the file at `path` (a regular file of at most 64 MiB).
Floor read_building_map(const std::string &path, const BuildingMapOptions &options);

// Reads `text` as if it were the file `path` (for errors and Floor::source).
Floor parse_building_map(const std::string &text, const std::string &path,
                         const BuildingMapOptions &options);

} // namespace envdesign::floor
