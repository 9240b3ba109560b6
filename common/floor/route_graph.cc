#include "route_graph.h"

#include "json_file.h"

#include "pddl/input_file.h"

#include <cmath>
#include <set>

namespace envdesign::floor {

namespace {

using nlohmann::json;

struct Node {
    int id = 0;
    std::string name;
    Point at;
};

int node_id(const JsonFile &file, const json &value, std::initializer_list<JsonKey> at,
            const std::string &what) {
    if (!value.is_number_integer() || value.get<long long>() < 0 ||
        value.get<long long>() > 1000000000)
        file.fail(at, what + " is not an integer id >= 0");
    return static_cast<int>(value.get<long long>());
}

std::string node_name(const json &properties) {
    if (properties.contains("name") && properties["name"].is_string())
        return properties["name"].get<std::string>();
    const json *metadata = properties.contains("metadata") ? &properties["metadata"] : nullptr;
    if (metadata && metadata->is_object() && metadata->contains("name") &&
        (*metadata)["name"].is_string())
        return (*metadata)["name"].get<std::string>();
    return "";
}

Node read_node(const JsonFile &file, std::size_t i, const json &feature) {
    const json &props = feature["properties"];
    Node n;
    n.id = node_id(file, props.contains("id") ? props["id"] : json(), {"features", i, "properties"},
                   "node " + std::to_string(i) + "'s id");
    // geometry is an object (geometry_type): `coordinates` may still be missing, and a const
    // json's operator[] of a missing key is undefined.
    const json &geometry = feature["geometry"];
    if (!geometry.contains("coordinates") || !geometry["coordinates"].is_array() ||
        geometry["coordinates"].size() < 2)
        file.fail({"features", i, "geometry"},
                  "node " + std::to_string(n.id) + " has no coordinates [x, y]");
    const json &c = geometry["coordinates"];
    n.at = {file.coordinate(c[0], {"features", i, "geometry", "coordinates", std::size_t(0)}, "x"),
            file.coordinate(c[1], {"features", i, "geometry", "coordinates", std::size_t(1)}, "y")};
    n.name = node_name(props);
    if (std::string why = name_problem(n.name); !why.empty())
        file.fail({"features", i, "properties"},
                  "the name of node " + std::to_string(n.id) + " " + why);
    return n;
}

// The feature's geometry type, or "" if it has none (nav2's edges may carry no coordinates).
std::string geometry_type(const json &feature) {
    if (!feature.contains("geometry") || !feature["geometry"].is_object())
        return "";
    const json &g = feature["geometry"];
    return g.contains("type") && g["type"].is_string() ? g["type"].get<std::string>() : "";
}

void check_crs(const JsonFile &file) {
    const json &doc = file.doc();
    if (!doc.contains("crs"))
        return;
    std::string text = doc["crs"].dump();
    for (const char *degrees : {"4326", "CRS84", "crs84"})
        if (text.find(degrees) != std::string::npos)
            file.fail({"crs"}, "coordinate system " + text +
                                   " is not supported: a route graph must be in metres");
}

struct Graph {
    std::map<int, Node> nodes;
    std::map<Edge, double> edges; // directed -> cost in metres (0: none given)
};

void read_edge(const JsonFile &file, std::size_t i, const json &props, Graph &g) {
    int from = node_id(file, props.contains("startid") ? props["startid"] : json(),
                       {"features", i, "properties"}, "edge " + std::to_string(i) + "'s startid");
    int to = node_id(file, props.contains("endid") ? props["endid"] : json(),
                     {"features", i, "properties"}, "edge " + std::to_string(i) + "'s endid");
    double cost = 0;
    if (props.contains("cost"))
        cost = file.coordinate(props["cost"], {"features", i, "properties", "cost"}, "cost");
    if (cost < 0)
        file.fail({"features", i, "properties", "cost"}, "cost is negative");
    if (from == to)
        return;                            // an edge from a node to itself is no move
    g.edges.emplace(Edge{from, to}, cost); // an edge given twice keeps its first cost
}

Graph read_features(const JsonFile &file) {
    const json &doc = file.doc();
    if (!doc.is_object() || !doc.contains("features") || !doc["features"].is_array())
        file.fail({}, "a route graph is a GeoJSON FeatureCollection with 'features'");
    Graph g;
    std::vector<std::pair<std::size_t, Edge>> edge_at; // to name the feature of a bad edge
    for (std::size_t i = 0; i < doc["features"].size(); ++i) {
        const json &f = doc["features"][i];
        if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object())
            file.fail({"features", i}, "feature " + std::to_string(i) + " has no properties");
        std::string type = geometry_type(f);
        if (type == "Point") {
            Node n = read_node(file, i, f);
            if (!g.nodes.emplace(n.id, n).second)
                file.fail({"features", i, "properties"},
                          "node id " + std::to_string(n.id) + " is given twice");
        } else if (f["properties"].contains("startid")) {
            read_edge(file, i, f["properties"], g);
            edge_at.push_back(
                {i, {f["properties"]["startid"].get<int>(), f["properties"]["endid"].get<int>()}});
        }
    }
    for (const auto &[i, e] : edge_at)
        for (int id : {e.from, e.to})
            if (!g.nodes.count(id))
                file.fail({"features", i, "properties"}, "edge " + std::to_string(i) +
                                                             " names node " + std::to_string(id) +
                                                             ", which is not in the graph");
    return g;
}

Floor to_floor(const Graph &g, const std::string &path) {
    Floor floor;
    floor.source = path;
    floor.level = "route graph";
    floor.route_graph = true;
    std::set<int> used;
    for (const auto &[e, cost] : g.edges) {
        floor.lanes.push_back(e);
        used.insert(e.from);
        used.insert(e.to);
        if (cost > 0)
            floor.given_length_dm[e] = std::max(1LL, std::llround(cost * 10));
    }
    for (int id : used) {
        const Node &n = g.nodes.at(id);
        floor.places.push_back({id, n.name, n.at, n.at});
    }
    return floor;
}

} // namespace

Floor read_route_graph(const std::string &path) {
    return parse_route_graph(pddl::read_input_file(path, MAX_MAP_FILE_BYTES), path);
}

Floor parse_route_graph(const std::string &text, const std::string &path) {
    JsonFile file(text, path);
    check_crs(file);
    Floor floor;
    try {
        floor = to_floor(read_features(file), path);
    } catch (const nlohmann::json::exception &e) { // a value of an unexpected type deep inside
        file.fail({}, std::string("not a route graph: ") + e.what());
    }
    if (floor.places.size() > MAX_PLACES)
        file.fail({"features"}, std::to_string(floor.places.size()) + " places, more than the " +
                                    std::to_string(MAX_PLACES) + " a floor may have");
    if (floor.places.empty())
        file.fail({"features"}, "the route graph has no edge between two nodes");
    return floor;
}

bool is_route_graph_path(const std::string &path) {
    auto ends = [&](const std::string &suffix) {
        return path.size() >= suffix.size() &&
               path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    return ends(".geojson") || ends(".json");
}

} // namespace envdesign::floor
