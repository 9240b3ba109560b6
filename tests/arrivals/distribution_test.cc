// Total variation distance and normalisation, expected values worked out by hand.

#include "arrivals/distribution.h"

#include <gtest/gtest.h>

namespace envdesign::arrivals {
namespace {

// 1/2 (|0.9 - 0.1| + |0.1 - 0.9|) = 0.8
TEST(TotalVariation, TwoTasksSwapped) {
    EXPECT_DOUBLE_EQ(total_variation({{"a", 0.9}, {"b", 0.1}}, {{"a", 0.1}, {"b", 0.9}}), 0.8);
}

TEST(TotalVariation, EqualIsZeroAndSymmetric) {
    Distribution p{{"a", 0.25}, {"b", 0.75}};
    Distribution q{{"a", 0.5}, {"c", 0.5}};
    EXPECT_DOUBLE_EQ(total_variation(p, p), 0);
    EXPECT_DOUBLE_EQ(total_variation(p, q), total_variation(q, p));
}

// A task in one only counts with 0 in the other: 1/2 (|0.25 - 0.5| + 0.75 + 0.5) = 0.75.
TEST(TotalVariation, TasksInOneOnly) {
    EXPECT_DOUBLE_EQ(total_variation({{"a", 0.25}, {"b", 0.75}}, {{"a", 0.5}, {"c", 0.5}}), 0.75);
    EXPECT_DOUBLE_EQ(total_variation({{"a", 1}}, {{"b", 1}}), 1); // disjoint
}

// Three tasks: 1/2 (0.1 + 0.3 + 0.2) = 0.3
TEST(TotalVariation, ThreeTasks) {
    EXPECT_NEAR(
        total_variation({{"a", 0.5}, {"b", 0.3}, {"c", 0.2}}, {{"a", 0.4}, {"b", 0.6}, {"c", 0.0}}),
        0.3, 1e-15);
}

// An empty estimate against a distribution: half its mass.
TEST(TotalVariation, EmptyDistribution) {
    EXPECT_DOUBLE_EQ(total_variation({}, {{"a", 0.4}, {"b", 0.6}}), 0.5);
}

TEST(Normalized, ScalesToOne) {
    Distribution d = normalized({{"a", 3}, {"b", 1}});
    EXPECT_DOUBLE_EQ(d["a"], 0.75);
    EXPECT_DOUBLE_EQ(d["b"], 0.25);
    EXPECT_TRUE(normalized({{"a", 0}}).empty());
    EXPECT_TRUE(normalized({}).empty());
}

TEST(Distribution, ToString) {
    EXPECT_EQ(to_string({{"pick", 0.9}, {"put", 0.1}}), "{pick: 0.9, put: 0.1}");
}

} // namespace
} // namespace envdesign::arrivals
