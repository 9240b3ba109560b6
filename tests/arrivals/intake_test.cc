// Bad samples: every kind is counted, none throws, floods are bounded.

#include "arrivals/intake.h"
#include "restaurant_drift.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace envdesign::arrivals {
namespace {

Arrival arrival(const std::string &task, int64_t sequence, const std::string &site = "s1") {
    return {"p", site, task, sequence, NOW_UTIME, "", ""};
}

TEST(Intake, AcceptsAndNumbers) {
    ArrivalIntake intake({});
    EXPECT_EQ(intake.check(arrival("a", 1), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", 2), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.counters().count(Verdict::ACCEPTED), 2);
    EXPECT_EQ(intake.counters().rejected(), 0);
}

TEST(Intake, EachBadKindIsCounted) {
    ArrivalIntake intake({});
    auto check = [&](Arrival a, bool known = true) { return intake.check(a, known, 0, NOW_UTIME); };
    EXPECT_EQ(check(arrival("a", 1), false), Verdict::UNKNOWN_PROBLEM);
    EXPECT_EQ(check(arrival("", 1)), Verdict::EMPTY_TASK);
    EXPECT_EQ(check(arrival(std::string(257, 'x'), 1)), Verdict::BAD_NAME);
    EXPECT_EQ(check(arrival("a\nb", 1)), Verdict::BAD_NAME);
    EXPECT_EQ(check(arrival("a", 1, std::string("s\0x", 3))), Verdict::BAD_NAME);
    Arrival big = arrival("a", 1);
    big.problem.assign((1 << 20) + 1, '(');
    EXPECT_EQ(check(big), Verdict::TOO_LARGE);
    EXPECT_EQ(check(arrival("a", 0)), Verdict::BAD_SEQUENCE);
    EXPECT_EQ(check(arrival("a", -5)), Verdict::BAD_SEQUENCE);
    const auto &c = intake.counters();
    EXPECT_EQ(c.received, 8);
    EXPECT_EQ(c.count(Verdict::UNKNOWN_PROBLEM), 1);
    EXPECT_EQ(c.count(Verdict::EMPTY_TASK), 1);
    EXPECT_EQ(c.count(Verdict::BAD_NAME), 3);
    EXPECT_EQ(c.count(Verdict::TOO_LARGE), 1);
    EXPECT_EQ(c.count(Verdict::BAD_SEQUENCE), 2);
    EXPECT_EQ(c.count(Verdict::ACCEPTED), 0);
}

// Absurd timestamps: zero, negative, the extremes of int64, 8 days ahead, 8 days old.
// 299 s ahead and 6 days old are fine (defaults: 300 s, 7 days); 301 s ahead is a skewed
// clock (Intake.SkewedClocksAreCountedNotRejected).
TEST(Intake, AbsurdTimestamps) {
    ArrivalIntake intake({});
    int64_t seq = 1;
    auto at = [&](int64_t utime) {
        Arrival a = arrival("a", seq++);
        a.utime = utime;
        return intake.check(a, true, 0, NOW_UTIME);
    };
    const std::vector<int64_t> absurd{0,
                                      -1,
                                      INT64_MIN,
                                      INT64_MAX,
                                      NOW_UTIME + int64_t{8} * 86400 * 1'000'000,
                                      NOW_UTIME - int64_t{8} * 86400 * 1'000'000};
    for (int64_t bad : absurd)
        EXPECT_EQ(at(bad), Verdict::BAD_TIMESTAMP) << bad;
    EXPECT_EQ(at(NOW_UTIME + 299'000'000), Verdict::ACCEPTED);
    EXPECT_EQ(at(NOW_UTIME - int64_t{6} * 86400 * 1'000'000), Verdict::ACCEPTED);
    EXPECT_EQ(intake.counters().count(Verdict::BAD_TIMESTAMP), 6);
}

// A publisher whose clock runs 10 minutes ahead (beyond --max-future 300 s): its arrivals
// are taken (the estimate uses their order, not their stamps) and counted as skewed.
// The old intake rejected them as bad_timestamp, so the estimate silently stopped.
TEST(Intake, SkewedClocksAreCountedNotRejected) {
    ArrivalIntake intake({});
    const int64_t ten_minutes = 600'000'000;
    for (int64_t s = 1; s <= 3; ++s) {
        Arrival a = arrival("a", s);
        a.utime = NOW_UTIME + ten_minutes;
        EXPECT_EQ(intake.check(a, true, 0, NOW_UTIME), Verdict::ACCEPTED);
        EXPECT_TRUE(intake.last_skewed());
    }
    EXPECT_EQ(intake.check(arrival("a", 4), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_FALSE(intake.last_skewed());
    EXPECT_EQ(intake.counters().clock_skewed, 3);
    EXPECT_NEAR(intake.counters().last_skew_s, 600, 1e-6);
    EXPECT_EQ(intake.counters().count(Verdict::BAD_TIMESTAMP), 0);
}

// 1, 2, 2 (duplicate), 1 (duplicate? no: a restart), 2, 5 (gap of 2: 3 and 4 lost), 4.
TEST(Intake, SequenceNumbers) {
    ArrivalIntake intake({});
    std::vector<Verdict> got;
    for (int64_t s : {1, 2, 2, 1, 2, 5, 4})
        got.push_back(intake.check(arrival("a", s), true, 0, NOW_UTIME));
    EXPECT_EQ(got, (std::vector<Verdict>{Verdict::ACCEPTED, Verdict::ACCEPTED, Verdict::DUPLICATE,
                                         Verdict::ACCEPTED, Verdict::ACCEPTED, Verdict::ACCEPTED,
                                         Verdict::DUPLICATE}));
    EXPECT_EQ(intake.counters().site_restarts, 1);
    EXPECT_EQ(intake.counters().sequence_gaps, 2);
}

// A sample with bad content still arrived: its number is no gap. 1 (empty task), 2 (bad
// timestamp), 3: no gap; 3 again is a duplicate even with an empty task? No: the content
// verdict comes first.
TEST(Intake, RejectedSamplesStillCountInTheSequence) {
    ArrivalIntake intake({});
    Arrival empty = arrival("", 1);
    Arrival old = arrival("a", 2);
    old.utime = 5;
    EXPECT_EQ(intake.check(empty, true, 0, NOW_UTIME), Verdict::EMPTY_TASK);
    EXPECT_EQ(intake.check(old, true, 0, NOW_UTIME), Verdict::BAD_TIMESTAMP);
    EXPECT_EQ(intake.check(arrival("a", 3), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("", 3), true, 0, NOW_UTIME), Verdict::EMPTY_TASK);
    EXPECT_EQ(intake.counters().sequence_gaps, 0);
    EXPECT_EQ(intake.counters().sequence_unseen, 0);
}

// Sites are numbered separately; a late joiner's first sample (sequence 40) is no gap.
TEST(Intake, SitesAreSeparate) {
    ArrivalIntake intake({});
    EXPECT_EQ(intake.check(arrival("a", 40, "s1"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", 1, "s2"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", 41, "s1"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.counters().sequence_gaps, 0);
    EXPECT_EQ(intake.counters().sequence_unseen, 39); // 1..39 of s1
}

// 10/s with a burst of 5: 5 at once pass, the 6th is limited; 0.1 s later one more passes.
TEST(Intake, RateLimitPerSite) {
    IntakeConfig config;
    config.max_rate = 10;
    config.burst = 5;
    ArrivalIntake intake(config);
    int64_t seq = 1;
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(intake.check(arrival("a", seq++), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", seq++), true, 0, NOW_UTIME), Verdict::RATE_LIMITED);
    EXPECT_EQ(intake.check(arrival("a", 1, "other"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", seq++), true, 0.1, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", seq++), true, 0.1, NOW_UTIME), Verdict::RATE_LIMITED);
    EXPECT_EQ(intake.counters().count(Verdict::RATE_LIMITED), 2);
    EXPECT_EQ(intake.counters().sequence_gaps, 0); // limited samples are not lost ones
}

// A flood of new sites stops at max_sites; known sites still get through.
TEST(Intake, SiteFloodIsBounded) {
    IntakeConfig config;
    config.max_sites = 3;
    ArrivalIntake intake(config);
    for (int i = 0; i < 100; ++i)
        intake.check(arrival("a", 1, "site" + std::to_string(i)), true, 0, NOW_UTIME);
    EXPECT_EQ(intake.counters().count(Verdict::ACCEPTED), 3);
    EXPECT_EQ(intake.counters().count(Verdict::TOO_MANY_SITES), 97);
    EXPECT_EQ(intake.check(arrival("a", 2, "site0"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
}

// First 2 logged, then one line per 10 s carrying the count left out.
TEST(LogThrottle, FirstFewThenPeriodic) {
    LogThrottle throttle(2, 10);
    EXPECT_TRUE(throttle.should_log(Verdict::EMPTY_TASK, 0).log);
    EXPECT_TRUE(throttle.should_log(Verdict::EMPTY_TASK, 0).log);
    for (int i = 0; i < 50; ++i)
        EXPECT_FALSE(throttle.should_log(Verdict::EMPTY_TASK, 5).log);
    EXPECT_TRUE(throttle.should_log(Verdict::DUPLICATE, 5).log); // kinds are separate
    auto d = throttle.should_log(Verdict::EMPTY_TASK, 10);
    EXPECT_TRUE(d.log);
    EXPECT_EQ(d.suppressed, 50);
    EXPECT_FALSE(throttle.should_log(Verdict::EMPTY_TASK, 11).log);
}

// After a flood stops, the summary of what was left out comes from overdue(), once.
TEST(LogThrottle, OverdueSummaries) {
    LogThrottle throttle(1, 10);
    throttle.should_log(Verdict::RATE_LIMITED, 0);
    for (int i = 0; i < 7; ++i)
        throttle.should_log(Verdict::RATE_LIMITED, 1);
    EXPECT_TRUE(throttle.overdue(9).empty());
    auto due = throttle.overdue(10);
    ASSERT_EQ(due.size(), 1u);
    EXPECT_EQ(due[0].first, Verdict::RATE_LIMITED);
    EXPECT_EQ(due[0].second, 7);
    EXPECT_TRUE(throttle.overdue(30).empty());
}

// Sequence numbers near INT64_MAX (issue 10): the counters of skipped and unseen numbers
// saturate instead of overflowing into negative values that the bridge would publish.
TEST(Intake, SequenceNumbersNearInt64MaxDoNotOverflow) {
    ArrivalIntake intake({});
    constexpr int64_t MAX = std::numeric_limits<int64_t>::max();
    EXPECT_EQ(intake.check(arrival("a", MAX, "s1"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", MAX, "s2"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", 1, "s3"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", MAX, "s3"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", 1, "s4"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.check(arrival("a", MAX, "s4"), true, 0, NOW_UTIME), Verdict::ACCEPTED);
    EXPECT_EQ(intake.counters().sequence_unseen, MAX);
    EXPECT_EQ(intake.counters().sequence_gaps, MAX);
}

} // namespace
} // namespace envdesign::arrivals
