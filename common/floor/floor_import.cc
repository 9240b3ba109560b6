#include "floor_import.h"

#include "floor_error.h"
#include "floor_json.h"
#include "route_graph.h"
#include "spec_text.h"
#include "zones.h"

#include "pddl/input_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace envdesign::floor {

namespace {

namespace fs = std::filesystem;

void check_at_least(double value, double least, const std::string &flag) {
    if (!std::isfinite(value) || value < least)
        throw FloorError(flag + " must be a finite number >= " + number_text(least) + ", not " +
                         number_text(value));
}

void check_options(const ImportOptions &o) {
    check_at_least(o.sight_m, 0, "--sight");
    check_at_least(o.candidates.tape_cost_per_m, 0, "--tape-cost");
    check_at_least(o.candidates.lane_cost_per_m, 0, "--lane-cost");
    check_at_least(o.weights.alpha, 0, "--alpha");
    check_at_least(o.weights.beta, 0, "--beta");
    check_at_least(o.weights.kappa, 0, "--kappa");
    check_at_least(o.weights.gamma, 0, "--gamma");
    if (o.weights.gamma > 1)
        throw FloorError("--gamma must be at most 1");
    if (o.weights.horizon < 1)
        throw FloorError("--horizon must be at least 1");
}

void write_file(const fs::path &path, const std::string &text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
}

Floor read_floor(const ImportOptions &o) {
    if (!is_route_graph_path(o.map)) {
        if (o.occupancy_yaml)
            throw FloorError("--map (an occupancy map) goes with a Nav2 route graph; a building "
                             "map's own walls block sight lines");
        return read_building_map(o.map, o.map_options);
    }
    if (o.map_options.level || o.map_options.graph != 0)
        throw FloorError("--level and --graph are for building maps, not route graphs");
    Floor floor = read_route_graph(o.map);
    if (o.occupancy_yaml) {
        floor.occupancy = std::make_shared<OccupancyGrid>(read_occupancy_map(*o.occupancy_yaml));
        floor.occupancy_source = *o.occupancy_yaml;
    }
    return floor;
}

} // namespace

FloorProblem build_floor_problem(const ImportOptions &options, std::vector<std::string> &warnings) {
    check_options(options);
    Floor floor = read_floor(options);
    InputTexts texts;
    if (options.tasks_csv)
        texts.tasks_csv = pddl::read_input_file(*options.tasks_csv);
    if (options.zones_json && options.candidates.zones)
        texts.zones_json = pddl::read_input_file(*options.zones_json, MAX_MAP_FILE_BYTES);
    return assemble_floor_problem(std::move(floor), options, texts, warnings);
}

FloorProblem assemble_floor_problem(Floor floor, const ImportOptions &options,
                                    const InputTexts &texts, std::vector<std::string> &warnings) {
    check_options(options);
    FloorProblem p;
    p.floor = std::move(floor);
    p.sight_m = options.sight_m;
    p.graph = build_floor_graph(p.floor, options.sight_m);
    std::vector<FloorTask> tasks =
        texts.tasks_csv
            ? parse_tasks_csv(*texts.tasks_csv, options.tasks_csv.value_or("tasks.csv"), p.floor)
            : default_tasks(p.floor);
    p.tasks = drop_unreachable(tasks, p.floor, p.graph, warnings);
    if (p.tasks.empty())
        throw FloorError("no task left: the robot's lanes connect none of the task pairs");
    std::vector<Zone> zones;
    if (texts.zones_json && options.candidates.zones)
        zones = parse_zones(*texts.zones_json, options.zones_json.value_or("zones.json"), warnings);
    p.candidates = make_candidates(p.floor, p.graph, zones, options.candidates, warnings);
    std::size_t edges = p.graph.robot.size() + p.graph.human_only.size();
    if (p.tasks.size() * edges > MAX_TASK_EDGES)
        throw FloorError(
            std::to_string(p.tasks.size()) + " tasks x " + std::to_string(edges) +
            " edges is more than " + std::to_string(MAX_TASK_EDGES) +
            " lines of problem files: give fewer tasks (--tasks) or a shorter --sight");
    p.weights = options.weights;
    return p;
}

ImportReport import_floor(const ImportOptions &options) {
    ImportReport report;
    FloorProblem p = build_floor_problem(options, report.warnings);
    fs::path dir(options.out_dir);
    std::error_code ec;
    fs::create_directories(dir / "tasks", ec);
    if (ec)
        throw std::runtime_error("cannot create " + (dir / "tasks").string() + ": " + ec.message());
    write_file(dir / "domain.pddl", domain_text());
    for (std::size_t i = 0; i < p.tasks.size(); ++i) {
        write_file(dir / robot_problem_path(p.tasks[i]), problem_text(p, i, false));
        write_file(dir / human_problem_path(p.tasks[i]), problem_text(p, i, true));
    }
    write_file(dir / "floor.json", floor_json(p).dump(1) + "\n");
    write_file(dir / "design.textproto", spec_text(p));
    report.spec_path = (dir / "design.textproto").string();
    report.places = p.floor.places.size();
    report.robot_edges = p.graph.robot.size();
    report.human_only_edges = p.graph.human_only.size();
    report.tasks = p.tasks.size();
    report.candidates = p.candidates.size();
    return report;
}

} // namespace envdesign::floor
