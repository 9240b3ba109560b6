#include "floor_json.h"

#include <filesystem>

namespace envdesign::floor {

namespace {

using nlohmann::json;

json point(const Point &p) { return json::array({p.x, p.y}); }

const Place &place_of(const FloorProblem &p, int vertex) {
    return p.floor.places[p.graph.index.at(vertex)];
}

json edges(const std::vector<Edge> &list) {
    json out = json::array();
    for (const Edge &e : list)
        out.push_back({object_name(e.from), object_name(e.to)});
    return out;
}

json places(const FloorProblem &p) {
    json out = json::array();
    for (const Place &pl : p.floor.places)
        out.push_back({{"object", object_name(pl.vertex)},
                       {"vertex", pl.vertex},
                       {"name", pl.name},
                       {"x", pl.at.x},
                       {"y", pl.at.y}});
    return out;
}

json tasks(const FloorProblem &p) {
    json out = json::array();
    for (std::size_t i = 0; i < p.tasks.size(); ++i) {
        const FloorTask &t = p.tasks[i];
        json task = {{"name", t.name()}, {"from", object_name(t.from)}, {"to", object_name(t.to)}};
        task["probability"] = task_probability(p, i).value_or(1.0 / p.tasks.size());
        out.push_back(task);
    }
    return out;
}

const char *kind_name(CandidateKind k) {
    return k == CandidateKind::TAPE ? "tape" : k == CandidateKind::LANE ? "lane" : "zone";
}

json candidate(const FloorProblem &p, const Candidate &c) {
    json segments = json::array();
    for (const Edge &pair : c.pairs)
        segments.push_back({point(place_of(p, pair.from).at), point(place_of(p, pair.to).at)});
    json edges = json::array();
    for (const InitEdit &e : c.edits)
        edges.push_back({object_name(e.edge.from), object_name(e.edge.to)});
    json out = {{"name", c.name},
                {"kind", kind_name(c.kind)},
                {"cost", c.cost},
                {"segments", segments},
                {"edges", edges}};
    if (c.kind == CandidateKind::ZONE) {
        out["zone_type"] = c.zone_type;
        json polygon = json::array();
        for (const Point &q : c.polygon)
            polygon.push_back(point(q));
        out["polygon"] = polygon;
    }
    return out;
}

json source(const FloorProblem &p) {
    std::error_code ec;
    std::filesystem::path map = std::filesystem::absolute(p.floor.source, ec);
    json out = {{"map", ec ? p.floor.source : map.string()},
                {"format", p.floor.route_graph ? "route_graph" : "building_map"},
                {"level", p.floor.level},
                {"graph", p.floor.graph},
                {"metres_per_unit", p.floor.scale}};
    if (!p.floor.occupancy_source.empty())
        out["occupancy_map"] = std::filesystem::absolute(p.floor.occupancy_source, ec).string();
    return out;
}

} // namespace

json floor_json(const FloorProblem &p) {
    json walls = json::array();
    for (const Segment &w : p.floor.walls)
        walls.push_back({point(w.a), point(w.b)});
    json candidates = json::array();
    for (const Candidate &c : p.candidates)
        candidates.push_back(candidate(p, c));
    return {{"format", "envdesign-floor"},
            {"version", 1},
            {"source", source(p)},
            {"sight_m", p.sight_m},
            {"places", places(p)},
            {"robot_edges", edges(p.graph.robot)},
            {"human_only_edges", edges(p.graph.human_only)},
            {"walls", walls},
            {"tasks", tasks(p)},
            {"candidates", candidates}};
}

} // namespace envdesign::floor
