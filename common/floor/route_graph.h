#pragma once
// Reading a Nav2 route graph (nav2_route's GeoJSON: a FeatureCollection of Point nodes with
// `properties.id`, and MultiLineString or LineString edges with `properties.startid`,
// `endid` and an optional `cost`) into a Floor. Coordinates are metres in the map frame
// (y up). Edges are directed: one robot edge each. An edge's `cost` > 0 is its length in
// metres (the robot's model and the human model alike); without it, the edge is as long as
// its segment. A node's label is `properties.name` (or `properties.metadata.name`).
//
//   Floor floor = read_route_graph("route.geojson");
//   floor.occupancy = ...   // --map: occupied cells block sight lines
//
// Faults throw pddl::ParseError at FILE:LINE:COL: malformed JSON, a node without an integer
// id >= 0, an id given twice, an edge naming an unknown node, a coordinate not finite or
// beyond MAX_COORDINATE_M, a geographic CRS (degrees, not metres), more than MAX_PLACES.

#include "floor.h"

#include <string>

namespace envdesign::floor {

Floor read_route_graph(const std::string &path);
Floor parse_route_graph(const std::string &text, const std::string &path);

// True if `path` names a route graph (*.geojson or *.json), not a building map.
bool is_route_graph_path(const std::string &path);

} // namespace envdesign::floor
