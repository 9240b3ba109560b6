#pragma once
// `envdesign floor import MAP -o DIR [...]`: an Open-RMF building map, or a Nav2 route graph
// (*.geojson, --map map.yaml) -> a design problem in DIR (design.textproto, domain.pddl,
// tasks/, floor.json), by FLOORS.md; docs/floors.md.
// `envdesign floor export DIR --design NAME,... -o OUT`: the design back in the site's
// formats (a map copy with the new lanes, GeoJSON of every chosen candidate, a keepout mask).
// `envdesign floor draw DIR [--design NAME,...] -o FILE.svg`: the floor as a picture (walls,
// lanes, sight lines, places, and the chosen candidates).
// Exit 0 written, 2 bad input (FILE:LINE:COL for a fault in a file), 1 a folder not writable.

#include "floor/floor_export.h"
#include "floor/floor_import.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace envdesign::cli {

struct FloorFlags {
    CLI::App *import = nullptr; // the `import` subcommand, to know it was chosen
    floor::ImportOptions options;
    std::string level;
    std::vector<std::string> candidates{"tape", "lane", "zones"};
    bool json = false;
    CLI::App *export_ = nullptr; // the `export` subcommand
    floor::ExportOptions export_options;
    std::vector<std::string> design;
    CLI::App *draw = nullptr; // the `draw` subcommand: floor.json (and a design) as SVG
    std::string draw_dir;
    std::string draw_out;
    std::vector<std::string> draw_design;
};

void add_floor_flags(CLI::App &command, FloorFlags &flags);
int run_floor(FloorFlags &flags);

} // namespace envdesign::cli
