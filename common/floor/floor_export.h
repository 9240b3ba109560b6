#pragma once
// `envdesign floor export`: a chosen design, back in the site's formats (FLOORS.md "Back to
// the site"), from an imported folder's floor.json and the map it names:
//   OUT/design.geojson        every chosen tape and lane (LineString) and zone (Polygon),
//                             metres in the places' frame, properties name, kind, cost
//   OUT/<map>.building.yaml   a building map: a copy with the chosen lanes added to the
//                             graph (two-way where both directions are added)
//   OUT/<graph>.geojson       a route graph: a copy with the chosen lanes as new edges
//   OUT/keepout.pgm, .yaml    a route graph imported with --map, and a BLOCKED zone chosen:
//                             a keepout mask with the map's size, resolution and origin
//                             (black: keep out, the cells whose centre is in a zone)
//
//   ExportReport r = export_design({"imported/", {"tape-v1-v2", "gap-barrier"}, "site/"});

#include <string>
#include <vector>

namespace envdesign::floor {

struct ExportOptions {
    std::string dir;                 // what `floor import -o` wrote
    std::vector<std::string> design; // candidate names
    std::string out_dir;
};

struct ExportReport {
    std::vector<std::string> written; // the files, in the order written
};

// Throws FloorError for a name that is no candidate, or a map that is gone; pddl::ParseError
// for a floor.json or map that does not read; std::runtime_error if OUT cannot be written.
ExportReport export_design(const ExportOptions &options);

} // namespace envdesign::floor
