#pragma once
// The two models of a floor (FLOORS.md "The two models"): the robot's edges are its lanes;
// people also believe in every sight line, a straight move between two places at most
// `sight` metres apart that crosses no wall. Lengths are whole decimetres.
//
//   FloorGraph graph = build_floor_graph(floor, 10.0);
//   graph.human_only   // sight lines that are not robot edges, sorted by (from, to)
//   length_dm(a, b)    // the cost of moving between two places

#include "floor.h"

#include <map>
#include <vector>

namespace envdesign::floor {

struct FloorGraph {
    std::vector<Edge> robot;          // = Floor::lanes
    std::vector<Edge> human_only;     // both directions of each sight line not on a lane
    std::map<int, std::size_t> index; // vertex number -> position in Floor::places
};

// Builds both models. `sight_m` >= 0.
FloorGraph build_floor_graph(const Floor &floor, double sight_m);

// |ab| in decimetres, rounded to the nearest integer (halves away from zero), at least 1.
long long length_dm(const Place &a, const Place &b);

// The length of edge e in the models: Floor::given_length_dm where the map gives it, else
// length_dm of its places.
long long edge_length_dm(const Floor &floor, const FloorGraph &graph, const Edge &e);

// Which places the robot can reach from the place `from` along its edges (vertex number ->
// reachable).
std::map<int, bool> robot_reachable(const FloorGraph &graph, int from);

// The sight lines among `places` (unordered pairs, vertex numbers, first < second) no wall
// of `walls_raw` and no occupied cell of `grid` (if any) blocks; walls are looked up in a
// grid of cells so that a large floor stays fast. Throws FloorError beyond MAX_SIGHT_LINES
// lines, or when the walls and cells near the pairs within sight, summed, are more than
// `max_wall_tests`.
std::vector<Edge> sight_lines(const std::vector<Place> &places, const std::vector<Segment> &walls,
                              const std::vector<Segment> &walls_raw, double sight_m,
                              const OccupancyGrid *grid = nullptr,
                              std::size_t max_wall_tests = MAX_WALL_TESTS);

} // namespace envdesign::floor
