#include "geometry.h"

#include <algorithm>
#include <cmath>

namespace envdesign::floor {

namespace {

int sign(double v) { return (v > 0) - (v < 0); }

bool same(const Point &a, const Point &b) { return a.x == b.x && a.y == b.y; }

// Position of c along s (0 at s.a, 1 at s.b) for c collinear with a non-degenerate s: the
// coordinate of larger extent keeps it exact when s is axis-parallel.
double along(const Segment &s, const Point &c) {
    double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    if (std::abs(dx) >= std::abs(dy))
        return (c.x - s.a.x) / dx;
    return (c.y - s.a.y) / dy;
}

// Both segments on one line: what they share is an interval of the sight line's parameter;
// it blocks unless it is empty or only the point p (0) or q (1).
bool collinear_overlap_blocks(const Segment &sight, const Segment &wall) {
    double t0 = along(sight, wall.a), t1 = along(sight, wall.b);
    double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
    if (lo > hi)
        return false;
    if (lo == hi)
        return lo > 0 && lo < 1;
    return true;
}

} // namespace

double orientation(const Point &a, const Point &b, const Point &c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool on_segment(const Segment &s, const Point &c) {
    if (orientation(s.a, s.b, c) != 0)
        return false;
    return std::min(s.a.x, s.b.x) <= c.x && c.x <= std::max(s.a.x, s.b.x) &&
           std::min(s.a.y, s.b.y) <= c.y && c.y <= std::max(s.a.y, s.b.y);
}

bool segments_meet(const Segment &s, const Segment &t) {
    int d1 = sign(orientation(t.a, t.b, s.a)), d2 = sign(orientation(t.a, t.b, s.b));
    int d3 = sign(orientation(s.a, s.b, t.a)), d4 = sign(orientation(s.a, s.b, t.b));
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return on_segment(t, s.a) || on_segment(t, s.b) || on_segment(s, t.a) || on_segment(s, t.b);
}

bool sight_blocked(const Segment &sight, const Segment &wall) {
    if (same(sight.a, sight.b))
        return false; // all it has is its endpoint
    if (!segments_meet(sight, wall))
        return false;
    bool collinear =
        orientation(sight.a, sight.b, wall.a) == 0 && orientation(sight.a, sight.b, wall.b) == 0;
    if (collinear)
        return collinear_overlap_blocks(sight, wall);
    // Not on one line: they share exactly one point, an endpoint of the sight line iff that
    // endpoint lies on the wall.
    return !on_segment(wall, sight.a) && !on_segment(wall, sight.b);
}

bool point_in_polygon(const Point &c, const std::vector<Point> &polygon) {
    std::size_t n = polygon.size();
    bool inside = false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Point &a = polygon[i], &b = polygon[j];
        if (on_segment({a, b}, c))
            return true;
        // Crossing number: the edge straddles the horizontal through c, right of c.
        if ((a.y > c.y) != (b.y > c.y)) {
            double o = orientation(a, b, c);
            if ((o > 0) == (b.y > a.y))
                inside = !inside;
        }
    }
    return n >= 3 && inside;
}

bool segment_meets_polygon(const Segment &s, const std::vector<Point> &polygon) {
    if (polygon.empty())
        return false;
    if (point_in_polygon(s.a, polygon) || point_in_polygon(s.b, polygon))
        return true;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        if (segments_meet(s, {polygon[j], polygon[i]}))
            return true;
    return false;
}

double distance(const Point &a, const Point &b) { return std::hypot(b.x - a.x, b.y - a.y); }

} // namespace envdesign::floor
