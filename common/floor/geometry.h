#pragma once
// Plane geometry of a floor: points, segments, and the two predicates FLOORS.md is written
// in, both built on the sign of one orientation determinant.
//
//   sight_blocked({p, q}, wall)    does a wall block the sight line p-q? It blocks when the
//                                  two segments share a point other than p or q: a wall
//                                  touching the line only at p or q does not block, one that
//                                  runs along it does.
//   segment_meets_polygon(s, poly) does s share a point with the closed polygon (boundary
//                                  included)?
//
// Arithmetic is in double precision in whatever frame the caller uses (the importer tests
// walls in the map's own coordinates, where a wall and a place that share a vertex have
// bit-identical coordinates, so "touches at p" is decided exactly).

#include <vector>

namespace envdesign::floor {

struct Point {
    double x = 0;
    double y = 0;
};

struct Segment {
    Point a;
    Point b;
};

// > 0 if a, b, c turn counter-clockwise, < 0 if clockwise, 0 if collinear.
double orientation(const Point &a, const Point &b, const Point &c);

// True if c lies on the closed segment s.
bool on_segment(const Segment &s, const Point &c);

// True if the closed segments s and t share at least one point.
bool segments_meet(const Segment &s, const Segment &t);

// True if `wall` shares with the sight line `sight` a point other than its endpoints.
bool sight_blocked(const Segment &sight, const Segment &wall);

// True if c lies inside the polygon or on its boundary. `polygon` lists the corners in
// order, closing edge implied; fewer than 3 corners is no area (only its edges count).
bool point_in_polygon(const Point &c, const std::vector<Point> &polygon);

// True if the closed segment s meets the closed polygon (an endpoint inside, or an edge met).
bool segment_meets_polygon(const Segment &s, const std::vector<Point> &polygon);

// Euclidean distance.
double distance(const Point &a, const Point &b);

} // namespace envdesign::floor
