#pragma once
// A floor as FLOORS.md reads it: the places of one fleet graph with their coordinates in
// metres, the lanes the robot drives, and the walls that block people's line of sight. The
// readers (building_map.h) make one; floor_graph.h turns it into the two models.
//
//   Floor floor = read_building_map("site.building.yaml", {.level = "L1", .graph = 0});
//   FloorGraph graph = build_floor_graph(floor, /*sight_m=*/10);

#include "geometry.h"
#include "occupancy_map.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace envdesign::floor {

// Bounds on what is read, so that a hostile or mistaken map is refused, not run for hours:
// sight lines cost O(places^2), each tested against the walls near it.
inline constexpr std::size_t MAX_PLACES = 10000;
inline constexpr std::size_t MAX_WALLS = 100000;
inline constexpr std::size_t MAX_TASKS = 10000;
inline constexpr double MAX_COORDINATE_M = 1e6; // |x|, |y| in metres
// Map, route graph and zone files: yaml-cpp holds about 100 bytes of memory a byte of YAML,
// so 8 MiB is about 1 GB at most (the largest rmf_demos map is 0.5 MB).
inline constexpr std::size_t MAX_MAP_FILE_BYTES = 8u << 20;
// Sight lines (unordered pairs) a floor may have: dense places and a long --sight make
// O(places^2) of them, each a line of every task's problems.
inline constexpr std::size_t MAX_SIGHT_LINES = 500000;
// Walls (and occupied-map cells) near a pair of places, summed over the pairs within sight:
// the work of finding the sight lines, a few seconds at most.
inline constexpr std::size_t MAX_WALL_TESTS = 20000000;
// Tasks x edges of both models: the lines the problem files would hold.
inline constexpr std::size_t MAX_TASK_EDGES = 4000000;

struct Place {
    int vertex = 0;   // the vertex number in the map; the PDDL object is "v<vertex>"
    std::string name; // the vertex's name in the map; empty if it has none
    Point at;         // metres, y up
    Point raw;        // as written in the map (pixels or metres): walls are tested here
};

// A directed edge between two places, by vertex number.
struct Edge {
    int from = 0;
    int to = 0;
    friend bool operator<(const Edge &a, const Edge &b) {
        return a.from != b.from ? a.from < b.from : a.to < b.to;
    }
    friend bool operator==(const Edge &a, const Edge &b) {
        return a.from == b.from && a.to == b.to;
    }
};

struct Floor {
    std::string source;             // the map file
    std::string level;              // the level read
    int graph = 0;                  // the fleet graph read (lanes' graph_idx)
    double scale = 1;               // metres per map unit
    std::vector<Place> places;      // ascending vertex number
    std::vector<Edge> lanes;        // robot edges: sorted, no duplicates, no self-loops
    std::vector<Segment> walls_raw; // map coordinates, as Place::raw
    std::vector<Segment> walls;     // metres, y up
    // Robot edges whose length the map gives (a Nav2 edge's cost), decimetres; the others
    // are as long as their segment.
    std::map<Edge, long long> given_length_dm;
    // Occupied cells that block sight lines as walls do (Nav2, --map); none for RMF maps.
    std::shared_ptr<const OccupancyGrid> occupancy;
    std::string occupancy_source; // its map.yaml, if any
    bool route_graph = false;     // read from a Nav2 route graph, not a building map
};

// "v<vertex>".
std::string object_name(int vertex);

// A name from a map or zone file (a place's label, a level, a zone's id) is written into the
// spec, the problems' comments and floor.json: at most this many bytes of UTF-8 text.
inline constexpr std::size_t MAX_NAME_BYTES = 256;

// Why `name` cannot be one ("is not UTF-8 text", "holds a control character", "is longer
// than ..."); empty if it can.
std::string name_problem(const std::string &name);

} // namespace envdesign::floor
