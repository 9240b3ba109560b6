// One active coordinator per bus (cluster/election.h), with hand-set clocks: who stands by
// for whom, when a standby takes over, and that the order is the same from every side.

#include "cluster/election.h"

#include <gtest/gtest.h>

namespace envdesign::cluster {
namespace {

using Clock = Election::Clock;
using namespace std::chrono_literals;

constexpr std::int64_t T0 = 1'700'000'000'000'000; // a wall clock, microseconds

envdesign::service_status_t status(const std::string &sender, std::int64_t started,
                                   const std::string &kind = "coordinator") {
    envdesign::service_status_t s{};
    s.sender = sender;
    s.kind = kind;
    s.started_utime = started;
    return s;
}

TEST(Election, AloneItDiscoversThenIsActive) {
    Clock::time_point t{};
    Election e("b", T0, {1.5, 3}, t);
    EXPECT_EQ(e.role(), Role::DISCOVERING);
    EXPECT_FALSE(e.update(t + 1400ms));
    EXPECT_EQ(e.role(), Role::DISCOVERING);
    auto change = e.update(t + 1600ms);
    ASSERT_TRUE(change);
    EXPECT_EQ(*change, "active: no coordinator that started earlier is on this bus");
    EXPECT_EQ(e.role(), Role::ACTIVE);
    EXPECT_FALSE(e.update(t + 5s)); // no change, no line
}

TEST(Election, WithoutDiscoveryItIsActiveAtOnce) {
    Election e("b", T0, {0, 3}, Clock::time_point{});
    EXPECT_EQ(e.role(), Role::ACTIVE);
}

TEST(Election, TheEarlierStartWinsFromBothSides) {
    Clock::time_point t{};
    Election first("z-first", T0, {1.5, 3}, t);       // started earlier, higher name
    Election second("a-second", T0 + 1, {1.5, 3}, t); // 1 us later
    first.heard(status("a-second", T0 + 1), t + 1s);
    second.heard(status("z-first", T0), t + 1s);
    first.update(t + 2s);
    second.update(t + 2s);
    EXPECT_EQ(first.role(), Role::ACTIVE);
    EXPECT_EQ(second.role(), Role::STANDBY);
    EXPECT_EQ(second.active(), "z-first");
}

TEST(Election, AtTheSameStartTheLowerNameWins) {
    Clock::time_point t{};
    Election a("coordinator/a", T0, {0, 3}, t);
    Election b("coordinator/b", T0, {0, 3}, t);
    a.heard(status("coordinator/b", T0), t);
    b.heard(status("coordinator/a", T0), t);
    EXPECT_FALSE(a.update(t + 10ms)); // stays active
    auto change = b.update(t + 10ms);
    ASSERT_TRUE(change);
    EXPECT_EQ(*change, "standing by: coordinator coordinator/a started earlier and is active on "
                       "this bus");
    EXPECT_EQ(a.role(), Role::ACTIVE);
    EXPECT_EQ(b.role(), Role::STANDBY);
}

TEST(Election, AStandbyTakesOverAfterTheSilence) {
    Clock::time_point t{};
    Election b("b", T0 + 5'000'000, {1.5, 3}, t);
    b.heard(status("a", T0), t + 500ms);
    b.update(t + 600ms);
    EXPECT_EQ(b.role(), Role::STANDBY);
    b.heard(status("a", T0), t + 1500ms); // its last status
    EXPECT_FALSE(b.update(t + 4400ms));   // 2.9 s of silence
    EXPECT_EQ(b.role(), Role::STANDBY);
    auto change = b.update(t + 4600ms); // 3.1 s
    ASSERT_TRUE(change);
    EXPECT_EQ(*change, "taking over: coordinator a has not been heard for 3 s");
    EXPECT_EQ(b.role(), Role::ACTIVE);
    // The old one restarted: a later start, so it stands by and this one stays active.
    b.heard(status("a", T0 + 9'000'000), t + 5s);
    EXPECT_FALSE(b.update(t + 5100ms));
    EXPECT_EQ(b.role(), Role::ACTIVE);
}

TEST(Election, OfThreeTheSecondTakesOverAndTheThirdStaysStandby) {
    Clock::time_point t{};
    Election c("c", T0 + 2, {0, 3}, t);
    c.heard(status("a", T0), t);
    c.heard(status("b", T0 + 1), t);
    c.update(t + 10ms);
    EXPECT_EQ(c.active(), "a");
    // a falls silent; b (a standby) still sends its status.
    for (auto at = 1s; at <= 5s; at += 1s)
        c.heard(status("b", T0 + 1), t + at);
    c.update(t + 5s);
    EXPECT_EQ(c.role(), Role::STANDBY);
    EXPECT_EQ(c.active(), "b");
}

TEST(Election, ItsOwnStatusAndOtherKindsDoNotCount) {
    Clock::time_point t{};
    Election e("b", T0 + 10, {0, 3}, t);
    e.heard(status("b", T0 + 10), t);       // its own, looped back
    e.heard(status("p", T0, "planner"), t); // a planner that started earlier
    e.heard(status("x", T0, "bridge"), t);  // a bridge
    e.heard(status("", T0), t);             // no name
    EXPECT_FALSE(e.update(t + 10ms));
    EXPECT_EQ(e.role(), Role::ACTIVE);
}

// Issue 21: two coordinators started with the same --name on one bus both took themselves
// for the only one and both answered every request. A status with this one's name but
// another start (or sender id) is another coordinator: the later stands by and says why.
TEST(Election, AnotherCoordinatorWithTheSameNameIsAPeer) {
    Clock::time_point t{};
    Election later("coordinator", T0 + 5, {0, 3}, t, 7);
    Election earlier("coordinator", T0, {0, 3}, t, 9);
    later.heard(status("coordinator", T0 + 5), t, 7); // its own status: ignored
    EXPECT_FALSE(later.update(t + 100ms));
    EXPECT_EQ(later.role(), Role::ACTIVE);
    later.heard(status("coordinator", T0), t + 200ms, 9);
    earlier.heard(status("coordinator", T0 + 5), t + 200ms, 7);
    auto change = later.update(t + 300ms);
    ASSERT_TRUE(change);
    EXPECT_EQ(*change, "standing by: another coordinator named coordinator started earlier and "
                       "is active on this bus; give each coordinator its own --name");
    EXPECT_EQ(later.role(), Role::STANDBY);
    EXPECT_FALSE(earlier.update(t + 300ms));
    EXPECT_EQ(earlier.role(), Role::ACTIVE);
}

// Started at the same microsecond: the signed sender id decides (bus keys), not the name a
// status claims; both sides agree.
TEST(Election, TiesGoToTheLowerSignedSenderId) {
    Clock::time_point t{};
    Election a("a", T0, {0, 3}, t, 50);
    Election z("z", T0, {0, 3}, t, 40);
    a.heard(status("z", T0), t, 40);
    z.heard(status("a", T0), t, 50);
    a.update(t + 100ms);
    z.update(t + 100ms);
    EXPECT_EQ(a.role(), Role::STANDBY);
    EXPECT_EQ(a.active(), "z");
    EXPECT_EQ(z.role(), Role::ACTIVE);
}

} // namespace
} // namespace envdesign::cluster
