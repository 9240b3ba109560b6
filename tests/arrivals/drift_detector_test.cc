// The drift detector's state machine: thresholds, evidence, hold-off, hysteresis, timeouts.

#include "arrivals/drift_detector.h"

#include <gtest/gtest.h>

namespace envdesign::arrivals {
namespace {

Distribution ab(double a) { return {{"a", a}, {"b", 1 - a}}; }

DriftConfig config() {
    DriftConfig c;
    c.threshold = 0.2;
    c.rearm_threshold = 0.1;
    c.min_samples = 10;
    c.holdoff_arrivals = 5;
    c.answer_timeout_s = 60;
    c.retry_s = 30;
    return c;
}

// TV(0.9/0.1, 0.65/0.35) = 0.25 >= 0.2, but 9 samples are not enough evidence.
TEST(DriftDetector, NeedsEnoughEvidence) {
    DriftDetector d(config(), ab(0.9));
    EXPECT_FALSE(d.observe(ab(0.65), 9, 0));
    EXPECT_DOUBLE_EQ(d.last_distance(), 0.25);
    EXPECT_TRUE(d.observe(ab(0.65), 10, 0));
}

// TV 0.15 < 0.2: nothing; TV 0.25: one request, then nothing while it is pending.
TEST(DriftDetector, OneRequestInFlight) {
    DriftDetector d(config(), ab(0.9));
    EXPECT_FALSE(d.observe(ab(0.75), 100, 0));
    EXPECT_EQ(d.state(), DriftState::ARMED);
    EXPECT_TRUE(d.observe(ab(0.65), 100, 1));
    EXPECT_EQ(d.state(), DriftState::PENDING);
    for (int i = 0; i < 100; ++i)
        EXPECT_FALSE(d.observe(ab(0.1), 100, 2));
    EXPECT_EQ(d.requests(), 1);
}

// The answer moves the reference: the next request needs TV 0.2 from the new D, not the old.
TEST(DriftDetector, TheAnswerMovesTheReference) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.65), 100, 0));
    d.answered(ab(0.65), ab(0.64));
    EXPECT_EQ(d.state(), DriftState::ARMED);
    EXPECT_DOUBLE_EQ(d.reference().at("a"), 0.65);
    for (int i = 0; i < 10; ++i)
        EXPECT_FALSE(d.observe(ab(0.5), 100, 1)); // TV 0.15
    EXPECT_TRUE(d.observe(ab(0.45), 100, 2));     // TV 0.2
}

// Noise around a design boundary: the estimate jumps between 0.71 and 0.69 (and back to 0.5
// and 0.52) for a long time. The first crossing asks once; after that the band of width 0.2
// around the evaluated D absorbs the noise: one request in all.
TEST(DriftDetector, NoiseDoesNotFlap) {
    DriftDetector d(config(), ab(0.5));
    int requests = 0;
    for (int i = 0; i < 1000; ++i) {
        Distribution estimate = ab(i % 2 ? 0.71 : 0.69);
        if (d.observe(estimate, 200, i)) {
            ++requests;
            d.answered(estimate, estimate);
        }
    }
    for (int i = 0; i < 1000; ++i)
        requests += d.observe(ab(i % 2 ? 0.52 : 0.6), 200, 1000 + i);
    EXPECT_EQ(requests, 1);
}

// Hold-off: after an answer, a request needs 5 fresh arrivals even when TV is large.
TEST(DriftDetector, HoldOff) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0)); // arrival 0 since the request
    d.answered(ab(0.6), ab(0.6));
    for (int i = 1; i < 5; ++i)
        EXPECT_FALSE(d.observe(ab(0.1), 100, 1)) << i; // arrivals 1..4: TV 0.5, held off
    EXPECT_TRUE(d.observe(ab(0.1), 100, 1));           // arrival 5
}

// No answer for answer_timeout_s (60): a timeout, and a new request.
TEST(DriftDetector, TimeoutAsksAgain) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0));
    for (int i = 0; i < 10; ++i)
        EXPECT_FALSE(d.observe(ab(0.6), 100, 59.9));
    EXPECT_TRUE(d.observe(ab(0.6), 100, 60));
    EXPECT_EQ(d.timeouts(), 1);
    EXPECT_EQ(d.requests(), 2);
}

// The same timeout on the clock alone, with no arrival: recheck() times the request out
// and asks again for the drifted estimate (an answer lost after the last arrival).
TEST(DriftDetector, RecheckTimesOutWithoutArrivals) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0));
    EXPECT_FALSE(d.observe(ab(0.6), 100, 1)); // within the hold-off (5): the timeout waives it
    EXPECT_FALSE(d.recheck(ab(0.6), 100, 59.9));
    EXPECT_EQ(d.state(), DriftState::PENDING);
    EXPECT_TRUE(d.recheck(ab(0.6), 100, 60));
    EXPECT_EQ(d.timeouts(), 1);
    EXPECT_EQ(d.requests(), 2);
}

// An answer for an older D leaves the estimate 0.3 away: HELD, asks again only after
// retry_s (30 s since the request), not at every arrival.
TEST(DriftDetector, StaleAnswerHoldsThenRetries) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0));
    d.answered(ab(0.9), ab(0.6));
    EXPECT_EQ(d.state(), DriftState::HELD);
    for (int i = 0; i < 20; ++i)
        EXPECT_FALSE(d.observe(ab(0.6), 100, 29));
    EXPECT_TRUE(d.observe(ab(0.6), 100, 30));
    EXPECT_EQ(d.state(), DriftState::PENDING);
}

// HELD re-arms once the estimate comes back within rearm_threshold (0.1) of the reference.
TEST(DriftDetector, HeldRearmsBelowTheLowThreshold) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0));
    d.answered(ab(0.9), ab(0.75)); // TV 0.15: between the thresholds
    EXPECT_EQ(d.state(), DriftState::HELD);
    EXPECT_FALSE(d.observe(ab(0.85), 100, 1)); // TV 0.05 < 0.1
    EXPECT_EQ(d.state(), DriftState::ARMED);
    for (int i = 0; i < 5; ++i)
        d.observe(ab(0.85), 100, 1);
    EXPECT_TRUE(d.observe(ab(0.65), 100, 2)); // armed: asks at once
}

// An answer before any arrival: nothing to compare with, armed.
TEST(DriftDetector, AnswerWithNoEstimateArms) {
    DriftDetector d(config(), ab(0.9));
    d.answered(ab(0.5), {});
    EXPECT_EQ(d.state(), DriftState::ARMED);
}

TEST(DriftDetector, ForceUnlessPending) {
    DriftDetector d(config(), ab(0.9));
    EXPECT_TRUE(d.force(0, ab(0.9)));
    EXPECT_FALSE(d.force(0, ab(0.9)));
    EXPECT_EQ(d.requests(), 1);
}

// The answer is for the D requested (0.6) but arrivals went on meanwhile (now 0.2): that is
// drift going on, not a stale answer; armed, and the next arrival past the hold-off asks
// for 0.2.
TEST(DriftDetector, AnswerAsRequestedRearmsWhileDriftGoesOn) {
    DriftDetector d(config(), ab(0.9));
    ASSERT_TRUE(d.observe(ab(0.6), 100, 0));
    for (int i = 0; i < 10; ++i)
        d.observe(ab(0.2), 100, 1);
    d.answered(ab(0.6), ab(0.2));
    EXPECT_EQ(d.state(), DriftState::ARMED);
    EXPECT_TRUE(d.observe(ab(0.2), 100, 2)); // 11 arrivals since the request
}

} // namespace
} // namespace envdesign::arrivals
