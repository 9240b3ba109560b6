// The Bus over memq://: typed round trips, and every kind of bad message counted, never
// thrown out of a handler.

#include "bus/bus.h"
#include "bus/channels.h"
#include "bus/lcm_url.h"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"

#include "bus_test_support.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <cstring>

namespace envdesign::bus {
namespace {

envdesign::planner_heartbeat_t beat() {
    envdesign::planner_heartbeat_t b{};
    b.sender = "planner/a";
    b.period_ms = 200;
    b.capacity = 2;
    b.jobs = {7, 8};
    b.num_jobs = 2;
    return b;
}

TEST(Bus, TypedRoundTrip) {
    Bus bus("memq://", quiet());
    std::vector<envdesign::planner_heartbeat_t> got;
    auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
        HEARTBEAT, [&](const envdesign::planner_heartbeat_t &b) { got.push_back(b); });
    bus.publish(HEARTBEAT, beat());
    drain(bus);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].sender, "planner/a");
    EXPECT_EQ(got[0].jobs, (std::vector<std::int64_t>{7, 8}));
    EXPECT_EQ(bus.malformed(), 0);
}

TEST(Bus, GarbageAndForeignTypesAreCountedNotDelivered) {
    Bus bus("memq://", quiet());
    int delivered = 0;
    auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
        HEARTBEAT, [&](const envdesign::planner_heartbeat_t &) { ++delivered; });
    const char garbage[] = "not an LCM message at all";
    bus.publish_raw(HEARTBEAT, garbage, sizeof garbage);
    bus.publish_raw(HEARTBEAT, garbage, 0);
    envdesign::job_t job{}; // a valid message of another type
    bus.publish(HEARTBEAT, job);
    std::string bytes = encode_message(beat());
    bus.publish_raw(HEARTBEAT, bytes.data(), static_cast<int>(bytes.size()) - 3); // truncated
    bytes += "xx";                                                                // trailing bytes
    bus.publish_raw(HEARTBEAT, bytes.data(), static_cast<int>(bytes.size()));
    drain(bus);
    EXPECT_EQ(delivered, 0);
    EXPECT_EQ(bus.malformed(), 5);
}

// lcm-gen's decoder resizes an array to the length it reads before checking the buffer:
// a negative length throws from inside it. The Bus must swallow that.
TEST(Bus, LyingArrayLengthsDoNotEscape) {
    Bus bus("memq://", quiet());
    int delivered = 0;
    auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
        HEARTBEAT, [&](const envdesign::planner_heartbeat_t &) { ++delivered; });
    std::string bytes = encode_message(beat());
    // num_jobs sits after the 8-byte hash, utime, sender, period_ms and capacity.
    std::size_t at = 8 + 8 + 4 + std::strlen("planner/a") + 1 + 4 + 2;
    for (std::int16_t lie : {std::int16_t(-1), std::int16_t(32767), std::int16_t(3)}) {
        std::string bad = bytes;
        bad[at] = static_cast<char>((lie >> 8) & 0xff);
        bad[at + 1] = static_cast<char>(lie & 0xff);
        bus.publish_raw(HEARTBEAT, bad.data(), static_cast<int>(bad.size()));
    }
    drain(bus);
    EXPECT_EQ(delivered, 0);
    EXPECT_EQ(bus.malformed(), 3);
}

TEST(Bus, HandlerExceptionsAreCaught) {
    Bus bus("memq://", quiet());
    auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
        HEARTBEAT, [](const envdesign::planner_heartbeat_t &) { throw std::runtime_error("x"); });
    bus.publish(HEARTBEAT, beat());
    bus.publish(HEARTBEAT, beat());
    drain(bus);
    EXPECT_EQ(bus.handler_errors(), 2);
}

TEST(Bus, UnsubscribesWhenTheSubscriptionGoes) {
    Bus bus("memq://", quiet());
    int delivered = 0;
    {
        auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
            HEARTBEAT, [&](const envdesign::planner_heartbeat_t &) { ++delivered; });
        bus.publish(HEARTBEAT, beat());
        drain(bus);
    }
    bus.publish(HEARTBEAT, beat());
    drain(bus);
    EXPECT_EQ(delivered, 1);
}

TEST(Bus, MoreThanLcmsDefaultQueueBetweenHandles) {
    Bus bus("memq://", quiet());
    int delivered = 0;
    auto s = bus.subscribe<envdesign::planner_heartbeat_t>(
        HEARTBEAT, [&](const envdesign::planner_heartbeat_t &) { ++delivered; });
    for (int i = 0; i < 500; ++i)
        bus.publish(HEARTBEAT, beat());
    drain(bus);
    EXPECT_EQ(delivered, 500);
}

TEST(LcmUrl, ReceiveBufferIsAddedToUdpmOnly) {
    EXPECT_EQ(with_receive_buffer("udpm://239.255.76.67:7667?ttl=0"),
              "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
    EXPECT_EQ(with_receive_buffer("udpm://239.255.76.67:7667"),
              "udpm://239.255.76.67:7667?recv_buf_size=4194304");
    EXPECT_EQ(with_receive_buffer("udpm://x:1?recv_buf_size=1000"),
              "udpm://x:1?recv_buf_size=1000");
    EXPECT_EQ(with_receive_buffer("memq://"), "memq://");
}

} // namespace
} // namespace envdesign::bus
