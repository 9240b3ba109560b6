// The sliding window and the exponential decay, expected values worked out by hand.

#include "arrivals/estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace envdesign::arrivals {
namespace {

DistributionEstimator feed(const std::string &config, const std::vector<std::string> &tasks) {
    DistributionEstimator e(parse_estimator_config(config));
    for (const auto &t : tasks)
        e.add(t);
    return e;
}

TEST(Estimator, EmptyBeforeTheFirstArrival) {
    DistributionEstimator e(parse_estimator_config("window:3"));
    EXPECT_TRUE(e.estimate().empty());
    EXPECT_EQ(e.effective_samples(), 0);
}

// a a b a: 3/4, 1/4.
TEST(Estimator, WindowFrequencies) {
    auto e = feed("window:4", {"a", "a", "b", "a"});
    EXPECT_DOUBLE_EQ(e.estimate()["a"], 0.75);
    EXPECT_DOUBLE_EQ(e.estimate()["b"], 0.25);
    EXPECT_EQ(e.effective_samples(), 4);
}

// a a b a b: the first a leaves the window of 4 -> a b a b: 1/2, 1/2.
TEST(Estimator, WindowForgetsTheOldest) {
    auto e = feed("window:4", {"a", "a", "b", "a", "b"});
    EXPECT_DOUBLE_EQ(e.estimate()["a"], 0.5);
    EXPECT_DOUBLE_EQ(e.estimate()["b"], 0.5);
    EXPECT_EQ(e.effective_samples(), 4);
}

// A task that left the window leaves the estimate entirely.
TEST(Estimator, WindowDropsTasksThatLeft) {
    auto e = feed("window:2", {"c", "a", "b"});
    EXPECT_EQ(e.estimate(), (Distribution{{"a", 0.5}, {"b", 0.5}}));
}

// Half-life 1: lambda = 1/2. a -> {a: 1}; b -> {a: 0.5, b: 1} = 1/3, 2/3;
// a -> {a: 1.25, b: 0.5}: a = 1.25 / 1.75 = 5/7, b = 2/7; samples 1.75.
TEST(Estimator, DecayHalvesPerHalfLife) {
    auto e = feed("decay:1", {"a", "b"});
    EXPECT_DOUBLE_EQ(e.estimate()["a"], 1.0 / 3);
    EXPECT_DOUBLE_EQ(e.estimate()["b"], 2.0 / 3);
    e.add("a");
    EXPECT_DOUBLE_EQ(e.estimate()["a"], 5.0 / 7);
    EXPECT_DOUBLE_EQ(e.estimate()["b"], 2.0 / 7);
    EXPECT_DOUBLE_EQ(e.effective_samples(), 1.75);
}

// Half-life 2: lambda = 2^(-1/2). After a b b: a = lambda^2 = 0.5, b = lambda + 1;
// a's share = 0.5 / (1.5 + 0.70710678) = 0.22654092.
TEST(Estimator, DecayFractionalFactor) {
    auto e = feed("decay:2", {"a", "b", "b"});
    EXPECT_NEAR(e.estimate()["a"], 0.5 / (1.5 + std::sqrt(0.5)), 1e-12);
}

// The effective sample size tends to 1 / (1 - lambda): half-life 10 -> 14.9317.
TEST(Estimator, DecayEffectiveSamplesConverge) {
    DistributionEstimator e(parse_estimator_config("decay:10"));
    for (int i = 0; i < 2000; ++i)
        e.add(i % 2 ? "a" : "b");
    EXPECT_NEAR(e.effective_samples(), 1 / (1 - std::pow(2.0, -0.1)), 1e-9);
    EXPECT_NEAR(e.estimate()["a"], 0.5, 0.05);
}

TEST(Estimator, ParsesAndPrintsConfig) {
    EXPECT_EQ(to_string(parse_estimator_config("window:200")), "window:200");
    EXPECT_EQ(to_string(parse_estimator_config("decay:12.5")), "decay:12.5");
    for (const char *bad : {"", "window", "window:0", "window:2.5", "window:-3", "decay:0",
                            "decay:x", "decay:1e999", "slide:5", "window:5x"})
        EXPECT_THROW(parse_estimator_config(bad), std::invalid_argument) << bad;
}

} // namespace
} // namespace envdesign::arrivals
