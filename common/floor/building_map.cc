#include "building_map.h"

#include "yaml_fields.h"

#include "pddl/input_file.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace envdesign::floor {

namespace {

struct Lane {
    int from = 0;
    int to = 0;
    bool bidirectional = false;
    int graph = 0;
};

std::string listed(const std::vector<std::string> &names) {
    std::string out;
    for (const auto &n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

// The level's node: the one named, or the only one.
YAML::Node choose_level(const YamlFields &yaml, const YAML::Node &root,
                        const std::optional<std::string> &wanted, std::string &name) {
    YAML::Node levels = yaml.required(root, "levels", "the building map");
    if (!levels.IsMap())
        yaml.fail(levels, "'levels' is not a map");
    std::vector<std::string> names;
    for (const auto &kv : levels) {
        std::string level = yaml.text(kv.first, "a level's name");
        if (std::find(names.begin(), names.end(), level) != names.end())
            yaml.fail(kv.first, "level '" + level + "' is given twice");
        names.push_back(level);
    }
    if (wanted) {
        if (!levels[*wanted].IsDefined())
            yaml.fail(levels, "no level '" + *wanted + "'; the levels are: " + listed(names));
        name = *wanted;
    } else if (names.size() != 1) {
        yaml.fail(levels,
                  std::to_string(names.size()) +
                      " levels and none chosen (--level): the levels are: " + listed(names));
    } else {
        name = names.front();
    }
    if (std::string why = name_problem(name); !why.empty())
        yaml.fail(levels, "the level's name " + why);
    return levels[name];
}

// A place's label goes into the spec's and problems' comments and floor.json.
void check_place_names(const YamlFields &yaml, const YAML::Node &level,
                       const std::vector<Place> &places) {
    YAML::Node list = level["vertices"];
    for (const Place &p : places)
        if (std::string why = name_problem(p.name); !why.empty())
            yaml.fail(list[p.vertex][3],
                      "the name of vertex " + std::to_string(p.vertex) + " " + why);
}

std::vector<Point> read_vertices(const YamlFields &yaml, const YAML::Node &level,
                                 std::vector<std::string> &names) {
    YAML::Node list = yaml.sequence(yaml.required(level, "vertices", "the level"), "'vertices'");
    std::vector<Point> points;
    for (std::size_t i = 0; i < list.size(); ++i) {
        YAML::Node v = list[i];
        std::string what = "vertex " + std::to_string(i);
        if (!v.IsSequence() || v.size() < 2)
            yaml.fail(v, what + " is not a list [x, y, ...]");
        points.push_back({yaml.number(v[0], what + "'s x"), yaml.number(v[1], what + "'s y")});
        names.push_back(v.size() > 3 && v[3].IsScalar() ? v[3].Scalar() : "");
    }
    return points;
}

int vertex_index(const YamlFields &yaml, const YAML::Node &node, std::size_t count,
                 const std::string &what) {
    long long i = yaml.integer(node, what);
    if (i < 0 || i >= static_cast<long long>(count))
        yaml.fail(node, what + " " + std::to_string(i) + " is not a vertex (the level has " +
                            std::to_string(count) + ")");
    return static_cast<int>(i);
}

std::vector<Lane> read_lanes(const YamlFields &yaml, const YAML::Node &level, std::size_t count) {
    std::vector<Lane> lanes;
    YAML::Node list = level["lanes"];
    if (!list.IsDefined() || list.IsNull())
        return lanes;
    for (const auto &lane : yaml.sequence(list, "'lanes'")) {
        if (!lane.IsSequence() || lane.size() < 2)
            yaml.fail(lane, "a lane is not a list [from, to, {parameters}]");
        Lane l;
        l.from = vertex_index(yaml, lane[0], count, "the lane's start");
        l.to = vertex_index(yaml, lane[1], count, "the lane's end");
        YAML::Node params = lane.size() > 2 ? lane[2] : YAML::Node();
        YAML::Node bidirectional = yaml.parameter(params, "bidirectional");
        l.bidirectional = bidirectional.IsDefined() && yaml.boolean(bidirectional, "bidirectional");
        YAML::Node graph = yaml.parameter(params, "graph_idx");
        long long g = graph.IsDefined() ? yaml.integer(graph, "graph_idx") : 0;
        if (g < 0 || g > 1000000)
            yaml.fail(graph, "graph_idx " + std::to_string(g) + " is not a graph number");
        l.graph = static_cast<int>(g);
        lanes.push_back(l);
    }
    return lanes;
}

// Metres per pixel: the mean over the measurements of distance / pixel length.
double measured_scale(const YamlFields &yaml, const YAML::Node &level,
                      const std::vector<Point> &vertices) {
    YAML::Node list = level["measurements"];
    if (!list.IsDefined() || list.IsNull() || (list.IsSequence() && list.size() == 0))
        yaml.fail(level, "the level has no measurements, so its pixels have no scale "
                         "(measure a distance in traffic-editor, or use cartesian_meters)");
    double sum = 0;
    for (const auto &m : yaml.sequence(list, "'measurements'")) {
        if (!m.IsSequence() || m.size() < 3)
            yaml.fail(m, "a measurement is not a list [from, to, {distance: [3, metres]}]");
        int i = vertex_index(yaml, m[0], vertices.size(), "the measurement's start");
        int j = vertex_index(yaml, m[1], vertices.size(), "the measurement's end");
        YAML::Node d = yaml.parameter(m[2], "distance");
        if (!d.IsDefined())
            yaml.fail(m, "the measurement has no distance");
        double metres = yaml.number(d, "the measured distance");
        double pixels = distance(vertices[i], vertices[j]);
        if (!(metres > 0) || !(pixels > 0))
            yaml.fail(m, "the measurement is not a positive distance between two points");
        sum += metres / pixels;
    }
    return sum / static_cast<double>(list.size());
}

std::vector<Edge> robot_edges(const std::vector<Lane> &lanes, int graph) {
    std::set<Edge> edges;
    for (const auto &l : lanes) {
        if (l.graph != graph || l.from == l.to)
            continue;
        edges.insert({l.from, l.to});
        if (l.bidirectional)
            edges.insert({l.to, l.from});
    }
    return {edges.begin(), edges.end()};
}

void check_graph(const YamlFields &yaml, const YAML::Node &level, const std::vector<Lane> &lanes,
                 int graph) {
    std::set<int> graphs;
    for (const auto &l : lanes)
        if (l.from != l.to)
            graphs.insert(l.graph);
    if (graphs.count(graph))
        return;
    std::vector<std::string> names;
    for (int g : graphs)
        names.push_back(std::to_string(g));
    yaml.fail(level, "no lane of graph " + std::to_string(graph) +
                         " on this level; its graphs are: " + listed(names));
}

} // namespace

Floor read_building_map(const std::string &path, const BuildingMapOptions &options) {
    return parse_building_map(pddl::read_input_file(path, MAX_MAP_FILE_BYTES), path, options);
}

namespace {

// True if vertices are in pixels of a reference image (y down), false if in metres.
bool in_pixels(const YamlFields &yaml, const YAML::Node &root) {
    YAML::Node system = root["coordinate_system"];
    if (!system.IsDefined() || system.IsNull())
        return true;
    std::string name = yaml.text(system, "coordinate_system");
    if (name == "reference_image")
        return true;
    if (name == "cartesian_meters")
        return false;
    yaml.fail(system, "coordinate system '" + name +
                          "' is not supported (only reference_image and cartesian_meters)");
}

std::vector<Segment> read_walls(const YamlFields &yaml, const YAML::Node &level,
                                const std::vector<Point> &vertices) {
    std::vector<Segment> walls;
    YAML::Node list = level["walls"];
    if (!list.IsDefined() || list.IsNull())
        return walls;
    yaml.sequence(list, "'walls'");
    if (list.size() > MAX_WALLS)
        yaml.fail(list, std::to_string(list.size()) + " walls, more than the " +
                            std::to_string(MAX_WALLS) + " a floor may have");
    for (const auto &wall : list) {
        if (!wall.IsSequence() || wall.size() < 2)
            yaml.fail(wall, "a wall is not a list [from, to, {parameters}]");
        int i = vertex_index(yaml, wall[0], vertices.size(), "the wall's start");
        int j = vertex_index(yaml, wall[1], vertices.size(), "the wall's end");
        walls.push_back({vertices[i], vertices[j]});
    }
    return walls;
}

Point to_metres(const Point &raw, bool pixels, double scale) {
    return pixels ? Point{raw.x * scale, -raw.y * scale} : raw;
}

void check_bounds(const YamlFields &yaml, const YAML::Node &level,
                  const std::vector<Point> &vertices, bool pixels, double scale) {
    YAML::Node list = level["vertices"];
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        Point m = to_metres(vertices[i], pixels, scale);
        if (!(std::abs(m.x) <= MAX_COORDINATE_M && std::abs(m.y) <= MAX_COORDINATE_M))
            yaml.fail(list[i], "vertex " + std::to_string(i) + " lies beyond " +
                                   std::to_string(static_cast<long>(MAX_COORDINATE_M)) +
                                   " m of the origin");
    }
}

std::vector<Place> places_of(const std::vector<Edge> &edges, const std::vector<Point> &vertices,
                             const std::vector<std::string> &names, bool pixels, double scale) {
    std::set<int> used;
    for (const auto &e : edges) {
        used.insert(e.from);
        used.insert(e.to);
    }
    std::vector<Place> places;
    for (int v : used)
        places.push_back({v, names[v], to_metres(vertices[v], pixels, scale), vertices[v]});
    return places;
}

Floor read_level(const YamlFields &yaml, const YAML::Node &root,
                 const BuildingMapOptions &options) {
    Floor floor;
    floor.source = yaml.path();
    floor.graph = options.graph;
    bool pixels = in_pixels(yaml, root);
    YAML::Node level = choose_level(yaml, root, options.level, floor.level);
    std::vector<std::string> names;
    std::vector<Point> vertices = read_vertices(yaml, level, names);
    std::vector<Lane> lanes = read_lanes(yaml, level, vertices.size());
    check_graph(yaml, level, lanes, options.graph);
    floor.scale = pixels ? measured_scale(yaml, level, vertices) : 1.0;
    check_bounds(yaml, level, vertices, pixels, floor.scale);
    floor.lanes = robot_edges(lanes, options.graph);
    floor.places = places_of(floor.lanes, vertices, names, pixels, floor.scale);
    check_place_names(yaml, level, floor.places);
    if (floor.places.size() > MAX_PLACES)
        yaml.fail(level, std::to_string(floor.places.size()) + " places, more than the " +
                             std::to_string(MAX_PLACES) + " a floor may have");
    floor.walls_raw = read_walls(yaml, level, vertices);
    for (const auto &w : floor.walls_raw)
        floor.walls.push_back(
            {to_metres(w.a, pixels, floor.scale), to_metres(w.b, pixels, floor.scale)});
    return floor;
}

} // namespace

Floor parse_building_map(const std::string &text, const std::string &path,
                         const BuildingMapOptions &options) {
    YamlFields yaml(path);
    YAML::Node root = yaml.load(text);
    if (!root.IsMap())
        throw pddl::ParseError({path, 1, 1}, "a building map is a YAML map with 'levels'");
    try {
        return read_level(yaml, root, options);
    } catch (const YAML::Exception &e) { // a node of an unexpected shape deep inside
        throw pddl::ParseError({path, e.mark.line + 1, e.mark.column + 1}, e.msg);
    }
}

std::string object_name(int vertex) { return "v" + std::to_string(vertex); }

} // namespace envdesign::floor
