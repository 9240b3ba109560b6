#include "floor_export.h"

#include "floor.h"
#include "floor_error.h"
#include "geometry.h"
#include "json_file.h"
#include "occupancy_map.h"
#include "yaml_fields.h"

#include "pddl/input_file.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace envdesign::floor {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

void write_file(const fs::path &path, const std::string &text, ExportReport &report) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
    report.written.push_back(path.string());
}

int vertex_of(const json &object) { return std::stoi(object.get<std::string>().substr(1)); }

// The chosen candidates of floor.json, in the spec's order.
std::vector<json> chosen(const json &floor, const std::vector<std::string> &names,
                         const std::string &where) {
    std::set<std::string> wanted(names.begin(), names.end()), found;
    std::vector<json> out;
    for (const json &c : floor["candidates"])
        if (wanted.count(c["name"].get<std::string>())) {
            out.push_back(c);
            found.insert(c["name"].get<std::string>());
        }
    for (const auto &name : names)
        if (!found.count(name))
            throw FloorError("no candidate '" + name + "' in " + where);
    return out;
}

json design_geojson(const std::vector<json> &design) {
    json features = json::array();
    for (const json &c : design) {
        json props = {{"name", c["name"]}, {"kind", c["kind"]}, {"cost", c["cost"]}};
        if (c["kind"] == "zone") {
            props["zone_type"] = c["zone_type"];
            json ring = c["polygon"];
            ring.push_back(ring.front()); // GeoJSON rings are closed
            features.push_back({{"type", "Feature"},
                                {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}},
                                {"properties", props}});
            continue;
        }
        for (const json &segment : c["segments"])
            features.push_back({{"type", "Feature"},
                                {"geometry", {{"type", "LineString"}, {"coordinates", segment}}},
                                {"properties", props}});
    }
    return {{"type", "FeatureCollection"}, {"name", "envdesign design"}, {"features", features}};
}

struct NewLane {
    int from = 0;
    int to = 0;
    bool bidirectional = false;
};

// The lanes the chosen lane candidates add: one two-way lane where both directions are added.
std::vector<NewLane> new_lanes(const std::vector<json> &design) {
    std::vector<NewLane> lanes;
    for (const json &c : design) {
        if (c["kind"] != "lane")
            continue;
        std::set<std::pair<int, int>> edges;
        for (const json &e : c["edges"])
            edges.insert({vertex_of(e[0]), vertex_of(e[1])});
        for (const auto &[a, b] : edges) {
            bool both = edges.count({b, a}) > 0;
            if (both && a > b)
                continue;
            lanes.push_back({a, b, both});
        }
    }
    return lanes;
}

std::string building_map_copy(const std::string &path, const json &source,
                              const std::vector<NewLane> &lanes) {
    YamlFields yaml(path);
    YAML::Node root = yaml.load(pddl::read_input_file(path, MAX_MAP_FILE_BYTES));
    YAML::Node level = root["levels"][source["level"].get<std::string>()];
    if (!level.IsMap())
        throw FloorError(path + " has no level '" + source["level"].get<std::string>() + "'");
    YAML::Node list = level["lanes"];
    for (const NewLane &l : lanes) {
        YAML::Node params;
        params["bidirectional"] =
            std::vector<YAML::Node>{YAML::Node(4), YAML::Node(l.bidirectional)};
        params["graph_idx"] = std::vector<int>{2, source["graph"].get<int>()};
        params["orientation"] = std::vector<YAML::Node>{YAML::Node(1), YAML::Node("")};
        params["speed_limit"] = std::vector<int>{3, 0};
        YAML::Node lane;
        lane.push_back(l.from);
        lane.push_back(l.to);
        lane.push_back(params);
        lane.SetStyle(YAML::EmitterStyle::Flow);
        list.push_back(lane);
    }
    YAML::Emitter out;
    out << root;
    return std::string(out.c_str()) + "\n";
}

std::string route_graph_copy(const std::string &path, const json &floor,
                             const std::vector<NewLane> &lanes) {
    JsonFile file(pddl::read_input_file(path, MAX_MAP_FILE_BYTES), path);
    json graph = file.doc();
    long long next = 0;
    for (const json &f : graph["features"])
        if (f["properties"].contains("id") && f["properties"]["id"].is_number_integer())
            next = std::max(next, f["properties"]["id"].get<long long>() + 1);
    std::map<int, json> at;
    for (const json &p : floor["places"])
        at[p["vertex"].get<int>()] = {p["x"], p["y"]};
    for (const NewLane &l : lanes)
        for (int k = 0; k < (l.bidirectional ? 2 : 1); ++k) {
            int a = k ? l.to : l.from, b = k ? l.from : l.to;
            graph["features"].push_back(
                {{"type", "Feature"},
                 {"geometry", {{"type", "MultiLineString"}, {"coordinates", {{at[a], at[b]}}}}},
                 {"properties", {{"id", next++}, {"startid", a}, {"endid", b}}}});
        }
    return graph.dump(1) + "\n";
}

void keepout_mask(const std::string &map_yaml, const std::vector<json> &design, const fs::path &out,
                  ExportReport &report) {
    OccupancyGrid grid = read_occupancy_map(map_yaml);
    std::vector<std::vector<Point>> zones;
    for (const json &c : design)
        if (c["kind"] == "zone" && c["zone_type"] == "BLOCKED") {
            zones.emplace_back();
            for (const json &p : c["polygon"])
                zones.back().push_back({p[0].get<double>(), p[1].get<double>()});
        }
    if (zones.empty())
        return;
    std::string pgm =
        "P5\n" + std::to_string(grid.width) + " " + std::to_string(grid.height) + "\n255\n";
    for (int top = 0; top < grid.height; ++top)
        for (int col = 0; col < grid.width; ++col) {
            int row = grid.height - 1 - top;
            Point centre{grid.origin.x + (col + 0.5) * grid.resolution,
                         grid.origin.y + (row + 0.5) * grid.resolution};
            bool keep_out = false;
            for (const auto &z : zones)
                keep_out = keep_out || point_in_polygon(centre, z);
            pgm += static_cast<char>(keep_out ? 0 : 254);
        }
    write_file(out / "keepout.pgm", pgm, report);
    std::ostringstream yaml;
    yaml.precision(17);
    yaml << "image: keepout.pgm\nmode: trinary\nresolution: " << grid.resolution << "\norigin: ["
         << grid.origin.x << ", " << grid.origin.y
         << ", 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    write_file(out / "keepout.yaml", yaml.str(), report);
}

} // namespace

ExportReport export_design(const ExportOptions &options) {
    fs::path dir(options.dir);
    std::string floor_path = (dir / "floor.json").string();
    JsonFile file(pddl::read_input_file(floor_path), floor_path);
    const json &floor = file.doc();
    if (!floor.is_object() || floor.value("format", "") != "envdesign-floor")
        file.fail({}, "not a floor.json written by envdesign floor import");
    std::vector<json> design = chosen(floor, options.design, floor_path);
    ExportReport report;
    fs::path out(options.out_dir);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec)
        throw std::runtime_error("cannot create " + out.string() + ": " + ec.message());
    write_file(out / "design.geojson", design_geojson(design).dump(1) + "\n", report);
    const json &source = floor["source"];
    std::string map = source["map"].get<std::string>();
    if (!fs::exists(map))
        throw FloorError("the map " + map + " that " + floor_path + " names is gone");
    std::vector<NewLane> lanes = new_lanes(design);
    fs::path copy = out / fs::path(map).filename();
    if (fs::equivalent(copy, map, ec))
        throw FloorError("the copy of the map would replace " + map + ": export to another folder");
    if (source["format"] == "route_graph") {
        write_file(copy, route_graph_copy(map, floor, lanes), report);
        if (source.contains("occupancy_map"))
            keepout_mask(source["occupancy_map"].get<std::string>(), design, out, report);
    } else {
        write_file(copy, building_map_copy(map, source, lanes), report);
    }
    return report;
}

} // namespace envdesign::floor
