#include "candidates.h"

#include "floor_error.h"

#include <cmath>
#include <map>
#include <set>

namespace envdesign::floor {

namespace {

const Place &place(const Floor &floor, const FloorGraph &graph, int vertex) {
    return floor.places[graph.index.at(vertex)];
}

double metres(const Floor &floor, const FloorGraph &graph, const Edge &pair) {
    return distance(place(floor, graph, pair.from).at, place(floor, graph, pair.to).at);
}

// Unordered pair -> its human-only edges, in (from, to) order.
std::map<Edge, std::vector<Edge>> human_only_pairs(const FloorGraph &graph) {
    std::map<Edge, std::vector<Edge>> pairs;
    for (const Edge &e : graph.human_only)
        pairs[{std::min(e.from, e.to), std::max(e.from, e.to)}].push_back(e);
    return pairs;
}

std::vector<Candidate> pair_candidates(const Floor &floor, const FloorGraph &graph,
                                       CandidateKind kind, double per_m) {
    std::vector<Candidate> out;
    for (const auto &[pair, edges] : human_only_pairs(graph)) {
        Candidate c;
        c.kind = kind;
        c.name = std::string(kind == CandidateKind::TAPE ? "tape-" : "lane-") +
                 object_name(pair.from) + "-" + object_name(pair.to);
        c.cost = round_cents(per_m * metres(floor, graph, pair));
        for (const Edge &e : edges)
            c.edits.push_back(kind == CandidateKind::TAPE ? InitEdit{EditModel::HUMAN, false, e}
                                                          : InitEdit{EditModel::ROBOT, true, e});
        c.pairs.push_back(pair);
        out.push_back(c);
    }
    return out;
}

bool meets(const Floor &floor, const FloorGraph &graph, const Edge &e, const Zone &zone) {
    Segment s{place(floor, graph, e.from).at, place(floor, graph, e.to).at};
    return segment_meets_polygon(s, zone.polygon);
}

Candidate zone_candidate(const Floor &floor, const FloorGraph &graph, const Zone &zone) {
    Candidate c;
    c.kind = CandidateKind::ZONE;
    c.name = zone.id;
    c.cost = zone.cost;
    c.polygon = zone.polygon;
    bool blocked = zone.type == ZoneType::BLOCKED;
    c.zone_type = blocked ? "BLOCKED" : "LINE_GUIDED";
    std::set<Edge> pairs;
    if (blocked)
        for (const Edge &e : graph.robot)
            if (meets(floor, graph, e, zone)) {
                c.edits.push_back({EditModel::BOTH, false, e});
                pairs.insert({std::min(e.from, e.to), std::max(e.from, e.to)});
            }
    for (const Edge &e : graph.human_only)
        if (meets(floor, graph, e, zone)) {
            c.edits.push_back({EditModel::HUMAN, false, e});
            pairs.insert({std::min(e.from, e.to), std::max(e.from, e.to)});
        }
    c.pairs.assign(pairs.begin(), pairs.end());
    return c;
}

} // namespace

double round_cents(double value) { return std::round(value * 100) / 100; }

std::vector<Candidate> make_candidates(const Floor &floor, const FloorGraph &graph,
                                       const std::vector<Zone> &zones,
                                       const CandidateOptions &options,
                                       std::vector<std::string> &warnings) {
    std::vector<Candidate> out;
    if (options.tapes)
        out = pair_candidates(floor, graph, CandidateKind::TAPE, options.tape_cost_per_m);
    if (options.lanes)
        for (auto &c : pair_candidates(floor, graph, CandidateKind::LANE, options.lane_cost_per_m))
            out.push_back(std::move(c));
    std::set<std::string> names;
    for (const auto &c : out)
        names.insert(c.name);
    for (const Zone &zone : options.zones ? zones : std::vector<Zone>{}) {
        Candidate c = zone_candidate(floor, graph, zone);
        if (c.edits.empty()) {
            warnings.push_back("zone '" + zone.id + "' is no candidate: it meets no edge it " +
                               "would remove");
            continue;
        }
        if (!names.insert(c.name).second)
            throw FloorError("zone '" + zone.id + "' has the name of another candidate");
        out.push_back(std::move(c));
    }
    return out;
}

} // namespace envdesign::floor
