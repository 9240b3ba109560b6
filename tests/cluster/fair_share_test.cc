// Fair shares of the planners between clients (cluster/fair_share.h).

#include "cluster/fair_share.h"

#include <gtest/gtest.h>

namespace envdesign::cluster {
namespace {

using namespace std::chrono_literals;

using Running = FairShare::Running;

const FairShare::Clock::time_point FAIR_T0 = FairShare::Clock::now();

FairShare::View fair_view(std::vector<std::uint64_t> queued, std::vector<Running> running,
                          int slots, FairShare::Counts incoming = {}) {
    return {std::move(queued), std::move(running), std::move(incoming), slots, FAIR_T0};
}

// A job of `client` that has run `seconds`, withdrawn `preemptions` times before.
Running fair_job(std::int64_t id, std::uint64_t client, double seconds, int preemptions = 0) {
    return {id, client, seconds, preemptions};
}

TEST(FairShare, UsageHalvesEveryHalfLifeAndCountsRunningJobs) {
    FairShare fair(2.0, 10.0);
    fair.add_service(1, 8, FAIR_T0);
    EXPECT_DOUBLE_EQ(fair.usage(1, {}, FAIR_T0), 8);
    EXPECT_NEAR(fair.usage(1, {}, FAIR_T0 + 10s), 4, 1e-9);
    EXPECT_NEAR(fair.usage(1, {}, FAIR_T0 + 20s), 2, 1e-9);
    EXPECT_NEAR(fair.usage(1, {fair_job(10, 1, 3), fair_job(11, 2, 5)}, FAIR_T0 + 10s), 7, 1e-9);
    fair.add_service(1, 1, FAIR_T0 + 10s);
    EXPECT_NEAR(fair.usage(1, {}, FAIR_T0 + 10s), 5, 1e-9);
    EXPECT_EQ(fair.usage(2, {}, FAIR_T0), 0) << "a client never seen has used nothing";
}

TEST(FairShare, TheLeastUsedClientGoesNext) {
    FairShare fair(2.0);
    fair.add_service(1, 50, FAIR_T0);
    fair.add_service(2, 5, FAIR_T0);
    std::vector<Running> running{fair_job(10, 1, 0), fair_job(11, 1, 0), fair_job(12, 2, 0),
                                 fair_job(13, 3, 0)};
    // queued: 1, 1, 2, 3 (oldest first); 8 slots, share 2: everyone below or at it
    EXPECT_EQ(fair.next(fair_view({1, 1, 2, 3}, running, 8)), 3u) << "3 used nothing";
    fair.add_service(3, 10, FAIR_T0);
    EXPECT_EQ(fair.next(fair_view({1, 1, 2, 3}, running, 8)), 2u);
    EXPECT_EQ(fair.next(fair_view({1, 1}, running, 8)), 0u) << "the oldest of one client";
    EXPECT_EQ(fair.next(fair_view({1, 4}, running, 8)), 1u) << "a new client first";
}

// Client 1 holds none of the two slots and has used a little more than 2: its share first.
// Much heavier than 2, it waits behind it.
TEST(FairShare, BelowItsShareGoesFirstUnlessMuchHeavier) {
    FairShare fair(2.0, 10.0, 2.0);
    fair.add_service(1, 3, FAIR_T0);
    fair.add_service(2, 2, FAIR_T0);
    std::vector<Running> running{fair_job(20, 2, 0), fair_job(21, 2, 0)};
    EXPECT_EQ(fair.next(fair_view({2, 1}, running, 2)), 1u);
    fair.add_service(1, 10, FAIR_T0);
    EXPECT_EQ(fair.next(fair_view({2, 1}, running, 2)), 0u);
}

TEST(FairShare, TheShareIsTheSlotsOverTheClientsWithWork) {
    EXPECT_EQ(FairShare::share({1, 2}, {fair_job(10, 3, 1)}, 6), 2);
    EXPECT_EQ(FairShare::share({1}, {fair_job(10, 1, 1)}, 6), 6);
    EXPECT_EQ(FairShare::share({1, 2, 3}, {}, 2), 1) << "at least one";
}

// The flood: one client holds every slot; a client below its share gets one at once
// from the over-share client's longest-running job, quantum or not.
TEST(FairShare, AClientOverItsShareYieldsAtOnce) {
    FairShare fair(2.0);
    std::vector<Running> running{fair_job(10, 1, 0.5), fair_job(11, 1, 0.3), fair_job(12, 1, 0.1)};
    EXPECT_FALSE(fair.victim(fair_view({1}, running, 3))) << "only its own jobs wait";
    auto taken = fair.victim(fair_view({2}, running, 3));
    ASSERT_TRUE(taken) << "share 1 of 3: 1 holds 3";
    EXPECT_EQ(taken->job, 10);
    EXPECT_EQ(taken->client, 2u);
    EXPECT_FALSE(fair.victim(fair_view({2}, running, 3, {{2, 1}}))) << "a slot is on its way to 2";
}

// A newcomer to a flood (usage 0 against 20 planner-seconds) takes every slot it asks for,
// not only its share: the flood's jobs that were never withdrawn, or are past their quantum.
TEST(FairShare, AMuchLighterClientTakesSlotsBeyondItsShare) {
    FairShare fair(2.0, 10.0, 2.0);
    fair.add_service(1, 20, FAIR_T0);
    std::vector<Running> running{fair_job(10, 1, 0.5), fair_job(11, 1, 1.0, 1)};
    auto taken = fair.victim(fair_view({2, 2}, running, 2, {{2, 1}}));
    ASSERT_TRUE(taken) << "2 holds one (on its way) and waits for another";
    EXPECT_EQ(taken->job, 10) << "job 11 was withdrawn before and is within its 4 s quantum";
    EXPECT_EQ(taken->client, 2u);
    EXPECT_FALSE(fair.victim(fair_view({2, 2}, {fair_job(11, 1, 1.0, 1)}, 2, {{2, 1}})));
    EXPECT_EQ(fair.victim(fair_view({2, 2}, {fair_job(11, 1, 4.5, 1)}, 2, {{2, 1}}))->job, 11)
        << "past its quantum";
    EXPECT_FALSE(fair.victim(fair_view({2}, running, 2, {{2, 1}}))) << "nothing more waits";
}

// No ping-pong: what rule 2 gave a much lighter client, rule 1 does not take back for the
// heavier one below its share, and nearly equal clients keep their shares.
TEST(FairShare, AMuchHeavierClientBelowItsShareDoesNotTakeBack) {
    FairShare fair(2.0, 10.0, 2.0);
    fair.add_service(1, 20, FAIR_T0);
    std::vector<Running> light{fair_job(20, 2, 0.2), fair_job(21, 2, 0.2)};
    EXPECT_FALSE(fair.victim(fair_view({1, 1}, light, 2)));
    EXPECT_EQ(fair.next(fair_view({1, 2}, {}, 2)), 1u) << "a freed slot goes to the lighter";
    FairShare even(2.0, 10.0, 2.0);
    even.add_service(1, 3, FAIR_T0);
    even.add_service(2, 2, FAIR_T0);
    EXPECT_FALSE(even.victim(fair_view({2}, {fair_job(10, 1, 0.5), fair_job(20, 2, 0.5)}, 2)))
        << "2 is lighter, but by less than the margin";
    EXPECT_EQ(even.victim(fair_view({1}, light, 2))->job, 20)
        << "below its share, not much heavier";
}

TEST(FairShare, AtTheirSharesAClientWithNoneTakesATurnPastAQuantum) {
    FairShare fair(2.0, 10.0, 100.0); // a margin no usage passes: turns alone
    EXPECT_FALSE(fair.victim(fair_view({2}, {fair_job(10, 1, 1.5)}, 1)));
    EXPECT_EQ(fair.victim(fair_view({2}, {fair_job(10, 1, 2.5)}, 1))->job, 10);
    EXPECT_FALSE(fair.victim(fair_view({2}, {fair_job(10, 1, 3.5, 1)}, 1)))
        << "withdrawn once: 4 s";
    EXPECT_EQ(fair.victim(fair_view({2}, {fair_job(10, 1, 8.5, 2)}, 1))->job, 10) << "twice: 8 s";
}

TEST(FairShare, AmongEqualHoldersTheMostUsedYieldsItsYoungest) {
    FairShare fair(2.0, 10.0, 1000.0);
    fair.add_service(1, 100, FAIR_T0);
    fair.add_service(2, 1, FAIR_T0);
    std::vector<Running> running{fair_job(10, 1, 3.0), fair_job(20, 2, 30.0)};
    EXPECT_EQ(fair.victim(fair_view({3}, running, 2))->job, 10);
    EXPECT_FALSE(fair.victim(fair_view({1, 2}, running, 2))) << "both at their share";
}

} // namespace
} // namespace envdesign::cluster
