// The floor importer's inputs (issue 21): the first byte picks the reader, the rest is that
// file's bytes.
//   0  an Open-RMF building map (YAML)               parse_building_map
//   1  a Nav2 route graph (GeoJSON)                   parse_route_graph
//   2  an occupancy map: map.yaml, a NUL, the PGM    parse_occupancy_map, over a fixed graph
//   3  a tasks CSV                                    over a fixed route graph
//   4  a zone file (JSON)                             over the same graph
// A reader either refuses with the floor's errors (pddl::ParseError at FILE:LINE:COL, or
// FloorError) or gives a floor whose every number is finite and in range; the import then
// assembles the problem as `envdesign floor import` does (assemble_floor_problem), and what
// it writes (floor.json, design.textproto, the domain and each task's problems) must be a
// design problem the spec reader loads with its full checks. Anything else aborts.

#include "floor/floor_error.h"
#include "floor/floor_import.h"
#include "floor/floor_json.h"
#include "floor/occupancy_map.h"
#include "floor/route_graph.h"
#include "floor/spec_text.h"

#include "envdesign/spec_t.hpp"
#include "pddl/parse_error.h"
#include "spec/design_spec.h"
#include "spec/file_source.h"
#include "spec/spec_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace envdesign;
using namespace envdesign::floor;

// Four named places on a one-way loop round an unnamed middle, 6 m apart: sight lines
// across the square and the middle give human-only edges, so candidates.
const char *FIXED_GRAPH = R"({"type": "FeatureCollection", "features": [
{"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}, "properties": {"id": 0, "name": "dock"}},
{"type": "Feature", "geometry": {"type": "Point", "coordinates": [6, 0]}, "properties": {"id": 1, "name": "a"}},
{"type": "Feature", "geometry": {"type": "Point", "coordinates": [6, 6]}, "properties": {"id": 2, "name": "b"}},
{"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 6]}, "properties": {"id": 3, "name": "c"}},
{"type": "Feature", "geometry": {"type": "Point", "coordinates": [3, 3]}, "properties": {"id": 4}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 10, "startid": 0, "endid": 1}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 11, "startid": 1, "endid": 2, "cost": 7.5}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 12, "startid": 2, "endid": 3}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 13, "startid": 3, "endid": 0}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 14, "startid": 4, "endid": 0}},
{"type": "Feature", "geometry": {"type": "MultiLineString"}, "properties": {"id": 15, "startid": 0, "endid": 4}}
]})";

// The largest length of an edge between two places within MAX_COORDINATE_M, decimetres.
const double MAX_LENGTH_DM = 2 * std::sqrt(2.0) * MAX_COORDINATE_M * 10 + 1;

[[noreturn]] void broken(const std::string &what) {
    std::fprintf(stderr, "floor_inputs: %s\n", what.c_str());
    std::abort();
}

bool finite_within(const Point &p, double bound) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::abs(p.x) <= bound &&
           std::abs(p.y) <= bound;
}

bool is_place(const FloorGraph &graph, int vertex) { return graph.index.count(vertex) == 1; }

void check_occupancy(const OccupancyGrid &g) {
    if (g.width < 1 || g.height < 1 || std::size_t(g.width) * g.height > MAX_MAP_CELLS ||
        g.occupied.size() != std::size_t(g.width) * g.height)
        broken("occupancy grid of a bad size");
    if (!(g.resolution > 0) || !std::isfinite(g.resolution) || !std::isfinite(g.origin.x) ||
        !std::isfinite(g.origin.y))
        broken("occupancy grid with a resolution or origin not finite");
}

void check_floor(const Floor &floor) {
    if (!(floor.scale > 0) || !std::isfinite(floor.scale))
        broken("scale not finite and > 0");
    if (floor.places.empty() || floor.places.size() > MAX_PLACES)
        broken("number of places out of range");
    for (std::size_t i = 0; i < floor.places.size(); ++i) {
        const Place &p = floor.places[i];
        if (p.vertex < 0 || (i > 0 && floor.places[i - 1].vertex >= p.vertex))
            broken("places not in ascending vertex order");
        if (!finite_within(p.at, MAX_COORDINATE_M) || !std::isfinite(p.raw.x) ||
            !std::isfinite(p.raw.y))
            broken("place " + object_name(p.vertex) + " not finite or beyond MAX_COORDINATE_M");
    }
    for (std::size_t i = 0; i < floor.lanes.size(); ++i) {
        const Edge &e = floor.lanes[i];
        if (e.from == e.to || (i > 0 && !(floor.lanes[i - 1] < e)))
            broken("lanes not sorted, repeated or a self-loop");
    }
    if (floor.walls.size() != floor.walls_raw.size() || floor.walls.size() > MAX_WALLS)
        broken("walls out of range");
    for (const Segment &w : floor.walls)
        if (!finite_within(w.a, MAX_COORDINATE_M) || !finite_within(w.b, MAX_COORDINATE_M))
            broken("a wall not finite or beyond MAX_COORDINATE_M");
    for (const auto &[edge, dm] : floor.given_length_dm)
        if (dm < 1 || dm > MAX_COORDINATE_M * 10 + 1)
            broken("a given length out of range");
    if (floor.occupancy)
        check_occupancy(*floor.occupancy);
}

void check_problem(const FloorProblem &p) {
    const FloorGraph &g = p.graph;
    for (const auto &list : {g.robot, g.human_only})
        for (const Edge &e : list) {
            if (!is_place(g, e.from) || !is_place(g, e.to) || e.from == e.to)
                broken("an edge not between two places");
            long long dm = edge_length_dm(p.floor, g, e);
            if (dm < 1 || dm > MAX_LENGTH_DM)
                broken("an edge's length out of range");
        }
    if (p.tasks.empty() || p.tasks.size() > MAX_TASKS ||
        p.tasks.size() * (g.robot.size() + g.human_only.size()) > MAX_TASK_EDGES)
        broken("number of tasks out of range");
    for (std::size_t i = 0; i < p.tasks.size(); ++i) {
        const FloorTask &t = p.tasks[i];
        if (!is_place(g, t.from) || !is_place(g, t.to) || t.from == t.to)
            broken("task " + t.name() + " not between two places");
        std::optional<double> probability = task_probability(p, i);
        if (probability && !(*probability >= 0 && *probability <= 1))
            broken("task " + t.name() + "'s probability not in [0, 1]");
    }
    for (const Candidate &c : p.candidates) {
        if (!std::isfinite(c.cost) || c.cost < 0 || c.edits.empty())
            broken("candidate " + c.name + " with a bad cost or no edit");
        for (const InitEdit &e : c.edits)
            if (!is_place(g, e.edge.from) || !is_place(g, e.edge.to))
                broken("candidate " + c.name + " edits an edge not between places");
    }
}

// What `envdesign floor import` writes, as the files of a spec_t, loaded with FULL checks.
void check_spec(const FloorProblem &p) {
    std::size_t size = p.graph.robot.size() + p.graph.human_only.size() + p.candidates.size();
    if (p.tasks.size() * size > 4000)
        return; // a large floor: loading every task's models per input would starve the fuzzer
    floor_json(p).dump(1);
    envdesign::spec_t message{};
    message.name = "floor/design.textproto";
    message.text = spec_text(p);
    message.files.push_back({"domain.pddl", domain_text()});
    for (std::size_t i = 0; i < p.tasks.size(); ++i) {
        message.files.push_back({robot_problem_path(p.tasks[i]), problem_text(p, i, false)});
        message.files.push_back({human_problem_path(p.tasks[i]), problem_text(p, i, true)});
    }
    message.num_files = static_cast<std::int16_t>(message.files.size());
    try {
        spec::SpecFile spec = spec::read_spec_text(message.text, message.name);
        spec::load_design_problem(spec, spec::MessageFiles(message));
    } catch (const pddl::ParseError &e) {
        broken(std::string("the imported floor is no design problem: ") + e.what() + "\n" +
               message.text);
    }
}

const Floor &fixed_floor() {
    static const Floor floor = parse_route_graph(FIXED_GRAPH, "fixed.geojson");
    return floor;
}

Floor read_input(int reader, const std::string &bytes, InputTexts &texts) {
    switch (reader) {
    case 0:
        return parse_building_map(bytes, "fuzz.building.yaml", {});
    case 1:
        return parse_route_graph(bytes, "fuzz.geojson");
    case 2: {
        std::size_t nul = bytes.find('\0');
        std::string yaml = bytes.substr(0, nul);
        std::string pgm = nul == std::string::npos ? "" : bytes.substr(nul + 1);
        Floor floor = fixed_floor();
        floor.occupancy = std::make_shared<OccupancyGrid>(
            parse_occupancy_map(yaml, "fuzz/map.yaml", [&](const std::string &) { return pgm; }));
        return floor;
    }
    case 3:
        texts.tasks_csv = bytes;
        return fixed_floor();
    default:
        texts.zones_json = bytes;
        return fixed_floor();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1)
        return 0;
    int reader = data[0] % 5;
    std::string bytes(reinterpret_cast<const char *>(data) + 1, size - 1);
    ImportOptions options;
    options.map = reader == 0 ? "fuzz.building.yaml" : "fuzz.geojson";
    options.tasks_csv = "fuzz/tasks.csv";
    options.zones_json = "fuzz/zones.json";
    InputTexts texts;
    Floor floor;
    try {
        floor = read_input(reader, bytes, texts);
    } catch (const pddl::ParseError &) {
        return 0;
    }
    check_floor(floor);
    std::vector<std::string> warnings;
    FloorProblem problem;
    try {
        problem = assemble_floor_problem(std::move(floor), options, texts, warnings);
    } catch (const pddl::ParseError &) {
        return 0;
    } catch (const FloorError &) {
        return 0;
    }
    check_problem(problem);
    check_spec(problem);
    return 0;
}
