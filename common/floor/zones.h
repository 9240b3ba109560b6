#pragma once
// Zones (FLOORS.md "Candidate modifications"): a JSON file in the shape of a VDA 5050
// zoneSet, {"zones": [{"zoneId", "zoneType", "vertices": [{"x", "y"}...], "cost"}]}, in
// metres in the places' frame (y up). BLOCKED zones are barriers, LINE_GUIDED zones areas
// marked as robot lanes; other VDA 5050 zone types are skipped with a warning.
//
//   std::vector<Zone> zones = read_zones("zones.json", warnings);

#include "geometry.h"

#include <string>
#include <vector>

namespace envdesign::floor {

enum class ZoneType { BLOCKED, LINE_GUIDED };

struct Zone {
    std::string id;
    ZoneType type = ZoneType::BLOCKED;
    std::vector<Point> polygon; // metres, at least 3 corners
    double cost = 0;            // finite, >= 0
};

// Reads the file at `path`. Throws pddl::ParseError at FILE:LINE:COL for malformed JSON, a
// missing or mistyped field, a zoneId given twice, fewer than 3 vertices, a coordinate that is
// not finite or beyond MAX_COORDINATE_M, a negative cost.
std::vector<Zone> read_zones(const std::string &path, std::vector<std::string> &warnings);
std::vector<Zone> parse_zones(const std::string &text, const std::string &path,
                              std::vector<std::string> &warnings);

} // namespace envdesign::floor
