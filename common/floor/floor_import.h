#pragma once
// `envdesign floor import`: an Open-RMF building map, or a Nav2 route graph (*.geojson) with
// an optional occupancy map, -> a design problem in a folder, by FLOORS.md. The entry point
// of the layer for the CLI (with floor_export.h, the way back). The layer, in order:
//
//   building_map.h, route_graph.h   a map -> Floor (places in metres, lanes, walls)
//   occupancy_map.h                 map_server's map.yaml + PGM -> cells that block sight
//   floor_graph.h                   Floor -> the two models (robot edges, human-only edges)
//   tasks.h, zones.h                the tasks (CSV or default), the zone file
//   candidates.h                    tape-vI-vJ, lane-vI-vJ, zones -> init edits
//   spec_text.h, floor_json.h       the files: spec, domain, problems, floor.json
//   geometry.h, yaml_fields.h, json_file.h   predicates; inputs with FILE:LINE:COL
//
//   ImportOptions options;
//   options.map = "warehouse.building.yaml";
//   options.out_dir = "warehouse";
//   ImportReport report = import_floor(options);   // warehouse/design.textproto, ...
//
// Bad input throws pddl::ParseError (FILE:LINE:COL) or FloorError; a file that cannot be
// written throws std::runtime_error.

#include "building_map.h"
#include "candidates.h"
#include "floor_problem.h"

#include <optional>
#include <string>
#include <vector>

namespace envdesign::floor {

struct ImportOptions {
    std::string map;
    std::string out_dir;
    BuildingMapOptions map_options;
    std::optional<std::string> tasks_csv;
    std::optional<std::string> zones_json;
    std::optional<std::string> occupancy_yaml; // Nav2: map_server's map.yaml (--map)
    double sight_m = 10;
    CandidateOptions candidates;
    Weights weights;
};

struct ImportReport {
    std::string spec_path; // out_dir/design.textproto
    std::size_t places = 0;
    std::size_t robot_edges = 0;
    std::size_t human_only_edges = 0;
    std::size_t tasks = 0;
    std::size_t candidates = 0;
    std::vector<std::string> warnings; // dropped tasks, skipped zones
};

// Reads, builds and checks the problem without writing anything.
FloorProblem build_floor_problem(const ImportOptions &options, std::vector<std::string> &warnings);

// The texts of the task and zone files, already read (tests, the fuzz target): nullopt for
// a file not given. Errors name them by options.tasks_csv and options.zones_json.
struct InputTexts {
    std::optional<std::string> tasks_csv;
    std::optional<std::string> zones_json;
};

// build_floor_problem from a floor already read (with its occupancy grid, if any): the same
// checks of the options, the same graph, tasks, candidates and bounds. options.map,
// options.tasks_csv, options.zones_json and options.occupancy_yaml are not opened.
FloorProblem assemble_floor_problem(Floor floor, const ImportOptions &options,
                                    const InputTexts &texts, std::vector<std::string> &warnings);

// build_floor_problem, then writes the files into options.out_dir (created if missing;
// files of the same names are replaced).
ImportReport import_floor(const ImportOptions &options);

} // namespace envdesign::floor
