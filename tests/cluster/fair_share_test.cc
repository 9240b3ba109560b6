// Fair shares of the planners between clients (cluster/fair_share.h).

#include "cluster/fair_share.h"

#include <gtest/gtest.h>

namespace envdesign::cluster {
namespace {

TEST(FairShare, TheClientHoldingFewestThenServedLeastGoesNext) {
    FairShare fair(2.0);
    fair.add_service(1, 50);
    fair.add_service(2, 5);
    // queued: 1, 1, 2, 3 (oldest first); 1 holds 2 slots, 2 holds 1, 3 holds 1
    FairShare::Held held{{1, 2}, {2, 1}, {3, 1}};
    EXPECT_EQ(fair.next({1, 1, 2, 3}, held), 3u) << "3 and 2 hold one each; 3 was served less";
    fair.add_service(3, 10);
    EXPECT_EQ(fair.next({1, 1, 2, 3}, held), 2u);
    EXPECT_EQ(fair.next({1, 1}, held), 0u) << "the oldest of one client";
    EXPECT_EQ(fair.next({1, 4}, held), 1u) << "a new client first";
}

TEST(FairShare, TheShareIsTheSlotsOverTheClientsWithWork) {
    EXPECT_EQ(FairShare::share({1, 2}, {{10, 3, 1, 0}}, 6), 2);
    EXPECT_EQ(FairShare::share({1}, {{10, 1, 1, 0}}, 6), 6);
    EXPECT_EQ(FairShare::share({1, 2, 3}, {}, 2), 1) << "at least one";
}

// The flood: one client holds every slot; a client below its share gets one at once
// from the over-share client's longest-running job, quantum or not.
TEST(FairShare, AClientOverItsShareYieldsAtOnce) {
    FairShare fair(2.0);
    std::vector<FairShare::Running> running{{10, 1, 0.5, 0}, {11, 1, 0.3, 0}, {12, 1, 0.1, 0}};
    FairShare::Held held{{1, 3}};
    EXPECT_FALSE(fair.victim({1}, running, held, 3)) << "only its own jobs wait";
    EXPECT_EQ(fair.victim({2}, running, held, 3), 10) << "share 1 of 3: 1 holds 3";
}

TEST(FairShare, AtTheirSharesAClientWithNoneTakesATurnPastAQuantum) {
    FairShare fair(2.0);
    FairShare::Held held{{1, 1}};
    EXPECT_FALSE(fair.victim({2}, {{10, 1, 1.5, 0}}, held, 1));
    EXPECT_EQ(fair.victim({2}, {{10, 1, 2.5, 0}}, held, 1), 10);
    EXPECT_FALSE(fair.victim({2}, {{10, 1, 3.5, 1}}, held, 1)) << "withdrawn once: 4 s";
    EXPECT_EQ(fair.victim({2}, {{10, 1, 8.5, 2}}, held, 1), 10) << "twice: 8 s";
}

TEST(FairShare, AmongEqualHoldersTheLongestServedYieldsItsYoungest) {
    FairShare fair(2.0);
    fair.add_service(1, 100);
    fair.add_service(2, 1);
    FairShare::Held held{{1, 1}, {2, 1}};
    EXPECT_EQ(fair.victim({3}, {{10, 1, 3.0, 0}, {20, 2, 30.0, 0}}, held, 2), 10);
    EXPECT_FALSE(fair.victim({1, 2}, {{10, 1, 3.0, 0}, {20, 2, 30.0, 0}}, held, 2))
        << "both at their share";
}

} // namespace
} // namespace envdesign::cluster
