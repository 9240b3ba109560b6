// The segment rules of FLOORS.md: a wall blocks a sight line when they share a point other
// than the line's endpoints; a segment meets a zone when it touches the closed polygon.

#include "floor/geometry.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

const Segment SIGHT{{0, 0}, {10, 0}};

TEST(SightBlocked, AWallAcrossTheMiddleBlocks) {
    EXPECT_TRUE(sight_blocked(SIGHT, {{5, -1}, {5, 1}}));
}

TEST(SightBlocked, AWallBesideTheLineDoesNot) {
    EXPECT_FALSE(sight_blocked(SIGHT, {{5, 0.5}, {5, 2}}));
    EXPECT_FALSE(sight_blocked(SIGHT, {{11, -1}, {11, 1}})); // beyond q
    EXPECT_FALSE(sight_blocked(SIGHT, {{0, 1}, {10, 1}}));   // parallel
}

TEST(SightBlocked, AWallTouchingOnlyAtAnEndpointDoesNot) {
    EXPECT_FALSE(sight_blocked(SIGHT, {{0, 0}, {0, 5}}));    // wall ends at p
    EXPECT_FALSE(sight_blocked(SIGHT, {{10, -3}, {10, 3}})); // q lies on the wall
    EXPECT_FALSE(sight_blocked(SIGHT, {{-4, 0}, {0, 0}}));   // collinear, meets only at p
    EXPECT_FALSE(sight_blocked(SIGHT, {{10, 0}, {14, 0}}));  // collinear, meets only at q
}

TEST(SightBlocked, AWallEndingOnTheLineBetweenTheEndpointsBlocks) {
    EXPECT_TRUE(sight_blocked(SIGHT, {{5, 0}, {5, 4}})); // a T onto the line
}

TEST(SightBlocked, AWallRunningAlongTheLineBlocks) {
    EXPECT_TRUE(sight_blocked(SIGHT, {{2, 0}, {4, 0}}));            // inside it
    EXPECT_TRUE(sight_blocked(SIGHT, {{-2, 0}, {3, 0}}));           // overlapping from before p
    EXPECT_TRUE(sight_blocked(SIGHT, {{0, 0}, {10, 0}}));           // the same segment
    EXPECT_TRUE(sight_blocked({{0, 0}, {3, 3}}, {{1, 1}, {2, 2}})); // diagonal, along
}

TEST(SightBlocked, APointWallInsideTheLineBlocksAndAtAnEndDoesNot) {
    EXPECT_TRUE(sight_blocked(SIGHT, {{5, 0}, {5, 0}}));
    EXPECT_FALSE(sight_blocked(SIGHT, {{0, 0}, {0, 0}}));
}

TEST(SegmentsMeet, TouchingCountsCrossingCountsApartDoesNot) {
    EXPECT_TRUE(segments_meet({{0, 0}, {2, 2}}, {{0, 2}, {2, 0}}));
    EXPECT_TRUE(segments_meet({{0, 0}, {2, 0}}, {{2, 0}, {3, 5}}));
    EXPECT_FALSE(segments_meet({{0, 0}, {2, 0}}, {{3, 0}, {4, 0}}));
    EXPECT_FALSE(segments_meet({{0, 0}, {2, 2}}, {{0, 1}, {1, 2}}));
}

const std::vector<Point> SQUARE{{0, 0}, {4, 0}, {4, 4}, {0, 4}};

TEST(PointInPolygon, InsideOnTheBoundaryAndOutside) {
    EXPECT_TRUE(point_in_polygon({2, 2}, SQUARE));
    EXPECT_TRUE(point_in_polygon({4, 2}, SQUARE)); // on an edge
    EXPECT_TRUE(point_in_polygon({0, 0}, SQUARE)); // a corner
    EXPECT_FALSE(point_in_polygon({5, 2}, SQUARE));
    EXPECT_FALSE(point_in_polygon({2, -0.01}, SQUARE));
    // Concave: an L, the notch is outside.
    std::vector<Point> l{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
    EXPECT_TRUE(point_in_polygon({0.5, 3}, l));
    EXPECT_FALSE(point_in_polygon({3, 3}, l));
}

TEST(SegmentMeetsPolygon, ThroughInsideTouchingAndMissing) {
    EXPECT_TRUE(segment_meets_polygon({{-1, 2}, {5, 2}}, SQUARE)); // straight through
    EXPECT_TRUE(segment_meets_polygon({{1, 1}, {2, 2}}, SQUARE));  // wholly inside
    EXPECT_TRUE(segment_meets_polygon({{4, 5}, {4, 4}}, SQUARE));  // ends at a corner
    EXPECT_TRUE(segment_meets_polygon({{-1, 4}, {5, 4}}, SQUARE)); // along the top edge
    EXPECT_FALSE(segment_meets_polygon({{-1, 5}, {5, 5}}, SQUARE));
    EXPECT_FALSE(segment_meets_polygon({{5, -1}, {9, 3}}, SQUARE));
}

TEST(Distance, IsEuclidean) { EXPECT_DOUBLE_EQ(distance({1, 1}, {4, 5}), 5.0); }

} // namespace
} // namespace envdesign::floor
