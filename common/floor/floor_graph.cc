#include "floor_graph.h"

#include "floor_error.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <unordered_map>

namespace envdesign::floor {

namespace {

// Walls by grid cell (metres). A wall is entered in the 3x3 cells around points sampled
// along it at most half a cell apart, so every cell it passes through holds it; a sight line
// is no longer than a cell, so the 3x3 cells around its endpoints hold every wall it meets.
class WallGrid {
public:
    WallGrid(const std::vector<Segment> &walls, double cell) : cell_(cell) {
        for (std::size_t w = 0; w < walls.size(); ++w)
            enter(walls[w], static_cast<int>(w));
    }

    // The walls near segment s (s no longer than a cell), each once.
    std::vector<int> near(const Segment &s) const {
        std::vector<int> found;
        // Where s meets a wall lies within one cell of either endpoint's cell.
        for (const Point &p : {s.a, s.b})
            for (long long dx = -1; dx <= 1; ++dx)
                for (long long dy = -1; dy <= 1; ++dy) {
                    auto it = cells_.find(key(cell_of(p.x) + dx, cell_of(p.y) + dy));
                    if (it != cells_.end())
                        found.insert(found.end(), it->second.begin(), it->second.end());
                }
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        return found;
    }

private:
    long long cell_of(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
    static long long key(long long cx, long long cy) { return cx * 4000003LL + cy; }

    void enter(const Segment &s, int wall) {
        double steps = std::ceil(distance(s.a, s.b) / (cell_ / 2));
        std::set<long long> keys;
        for (double k = 0; k <= steps; ++k) {
            double t = steps > 0 ? k / steps : 0;
            long long cx = cell_of(s.a.x + t * (s.b.x - s.a.x));
            long long cy = cell_of(s.a.y + t * (s.b.y - s.a.y));
            for (long long dx = -1; dx <= 1; ++dx)
                for (long long dy = -1; dy <= 1; ++dy)
                    keys.insert(key(cx + dx, cy + dy));
        }
        for (long long k : keys)
            cells_[k].push_back(wall);
    }

    double cell_;
    std::unordered_map<long long, std::vector<int>> cells_;
};

// A cell no smaller than the sight distance, and coarse enough that no wall of a floor
// within MAX_COORDINATE_M is entered in more than a few thousand cells, and all the walls
// together in a few million (issue 21: ten thousand walls across the whole floor, a 64 KB
// map, were each entered in thousands of cells: minutes and gigabytes).
double cell_size(const std::vector<Segment> &walls, double sight_m) {
    double extent = 0, total = 0;
    for (const auto &w : walls) {
        extent = std::max(extent, distance(w.a, w.b));
        total += distance(w.a, w.b);
    }
    return std::max({sight_m, 1.0, extent / 512, total / 100000});
}

bool blocked(const Segment &raw, const std::vector<int> &near,
             const std::vector<Segment> &walls_raw) {
    for (int w : near)
        if (sight_blocked(raw, walls_raw[w]))
            return true;
    return false;
}

// About how many cells of `grid` the segment visits (OccupancyGrid::blocks), at most the
// grid's width plus height.
std::size_t cells_crossed(const OccupancyGrid &grid, const Segment &s) {
    double span = (std::abs(s.b.x - s.a.x) + std::abs(s.b.y - s.a.y)) / grid.resolution;
    return static_cast<std::size_t>(std::min(span, double(grid.width) + grid.height)) + 2;
}

} // namespace

std::vector<Edge> sight_lines(const std::vector<Place> &places, const std::vector<Segment> &walls,
                              const std::vector<Segment> &walls_raw, double sight_m,
                              const OccupancyGrid *grid, std::size_t max_wall_tests) {
    WallGrid walls_near(walls, cell_size(walls, sight_m));
    std::vector<std::size_t> by_x(places.size());
    for (std::size_t i = 0; i < by_x.size(); ++i)
        by_x[i] = i;
    std::sort(by_x.begin(), by_x.end(),
              [&](std::size_t a, std::size_t b) { return places[a].at.x < places[b].at.x; });
    std::vector<Edge> lines;
    std::size_t tests = 0; // wall tests so far
    for (std::size_t i = 0; i < by_x.size(); ++i) {
        const Place &p = places[by_x[i]];
        for (std::size_t j = i + 1; j < by_x.size(); ++j) {
            const Place &q = places[by_x[j]];
            if (q.at.x - p.at.x > sight_m)
                break;
            if (distance(p.at, q.at) > sight_m)
                continue;
            std::vector<int> near = walls_near.near({p.at, q.at});
            tests += near.size() + 1 + (grid ? cells_crossed(*grid, {p.at, q.at}) : 0);
            if (tests > max_wall_tests)
                throw FloorError("more than " + std::to_string(max_wall_tests) +
                                 " tests of a sight line against a wall: the places and walls "
                                 "are too dense for the sight distance (lower --sight)");
            if (blocked({p.raw, q.raw}, near, walls_raw))
                continue;
            if (grid && grid->blocks({p.at, q.at}))
                continue;
            lines.push_back({std::min(p.vertex, q.vertex), std::max(p.vertex, q.vertex)});
            if (lines.size() > MAX_SIGHT_LINES)
                throw FloorError("more than " + std::to_string(MAX_SIGHT_LINES) +
                                 " sight lines: the places are too dense for the sight "
                                 "distance (lower --sight)");
        }
    }
    std::sort(lines.begin(), lines.end());
    return lines;
}

FloorGraph build_floor_graph(const Floor &floor, double sight_m) {
    FloorGraph graph;
    graph.robot = floor.lanes;
    for (std::size_t i = 0; i < floor.places.size(); ++i)
        graph.index[floor.places[i].vertex] = i;
    std::set<Edge> robot(floor.lanes.begin(), floor.lanes.end());
    std::set<Edge> human_only;
    for (const Edge &e :
         sight_lines(floor.places, floor.walls, floor.walls_raw, sight_m, floor.occupancy.get()))
        for (const Edge &d : {e, Edge{e.to, e.from}})
            if (!robot.count(d))
                human_only.insert(d);
    graph.human_only.assign(human_only.begin(), human_only.end());
    return graph;
}

long long length_dm(const Place &a, const Place &b) {
    return std::max(1LL, std::llround(distance(a.at, b.at) * 10));
}

long long edge_length_dm(const Floor &floor, const FloorGraph &graph, const Edge &e) {
    auto given = floor.given_length_dm.find(e);
    if (given != floor.given_length_dm.end())
        return given->second;
    return length_dm(floor.places[graph.index.at(e.from)], floor.places[graph.index.at(e.to)]);
}

std::map<int, bool> robot_reachable(const FloorGraph &graph, int from) {
    std::map<int, std::vector<int>> out;
    for (const Edge &e : graph.robot)
        out[e.from].push_back(e.to);
    std::map<int, bool> seen;
    for (const auto &[v, _] : graph.index)
        seen[v] = false;
    std::deque<int> queue{from};
    seen[from] = true;
    while (!queue.empty()) {
        int v = queue.front();
        queue.pop_front();
        for (int w : out[v])
            if (!seen[w]) {
                seen[w] = true;
                queue.push_back(w);
            }
    }
    return seen;
}

} // namespace envdesign::floor
