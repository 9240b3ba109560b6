// StatusPublisher and StatusBoard over memq://: what the bus knows goes into every status,
// once a period, and survives the LCM encoding.

#include "bus/bus.h"
#include "bus/channels.h"
#include "bus/codec.h"
#include "bus/status.h"

#include "bus_test_support.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <thread>

namespace envdesign::bus {
namespace {

TEST(Status, FirstAtOnceThenOnceAPeriod) {
    Bus bus("memq://", quiet());
    StatusBoard board(bus);
    StatusPublisher status(bus, "planner", "planner/a", 0.2);
    int fills = 0;
    auto fill = [&](envdesign::service_status_t &s) {
        ++fills;
        s.jobs_done = 7;
    };
    EXPECT_TRUE(status.tick(fill));
    EXPECT_FALSE(status.tick(fill)); // within the period
    drain(bus);
    ASSERT_TRUE(board.heard("planner"));
    EXPECT_FALSE(board.heard("coordinator"));
    const auto &s = board.services().at(ServiceId{"planner/a", status.started_utime()});
    EXPECT_EQ(s.kind, "planner");
    EXPECT_EQ(s.version, version());
    EXPECT_EQ(s.period_ms, 200);
    EXPECT_EQ(s.jobs_done, 7);
    EXPECT_EQ(fills, 1);
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    EXPECT_TRUE(status.tick(fill));
    drain(bus);
    EXPECT_GT(board.services().at(ServiceId{"planner/a", status.started_utime()}).uptime_s, 0.2);
}

TEST(Status, CarriesTheBusCountsAndDrops) {
    Bus bus("memq://", quiet());
    bus.reject(JOB, "a test");
    bus.reject(JOB, "another");
    StatusPublisher status(bus, "bridge", "bridge/a");
    auto s = status.snapshot([](envdesign::service_status_t &s) {
        add_drop(s, "dds:arrivals", "duplicate", 3);
        add_drop(s, "dds:arrivals", "bad_timestamp", 1);
    });
    EXPECT_EQ(s.malformed, 2);
    EXPECT_EQ(s.handler_errors, 0);
    // The LCM encoding keeps the parallel arrays together.
    envdesign::service_status_t back;
    std::string bytes = encode_message(s);
    ASSERT_TRUE(decode_message(bytes.data(), static_cast<int>(bytes.size()), back));
    ASSERT_EQ(back.num_drops, 2);
    EXPECT_EQ(back.drop_channels[1], "dds:arrivals");
    EXPECT_EQ(back.drop_reasons[1], "bad_timestamp");
    EXPECT_EQ(back.drop_counts[0], 3);
    EXPECT_EQ(back.sender, "bridge/a");
    EXPECT_EQ(back.malformed, 2);
}

TEST(Status, BoardKeepsTheLastOfEachSender) {
    Bus bus("memq://", quiet());
    StatusBoard board(bus);
    envdesign::service_status_t s{};
    s.kind = "coordinator";
    s.sender = "c";
    s.started_utime = 1000;
    s.planners = 1;
    bus.publish(STATUS, s);
    s.planners = 2;
    bus.publish(STATUS, s);
    s.sender = ""; // nameless: not a service
    bus.publish(STATUS, s);
    drain(bus);
    ASSERT_EQ(board.services().size(), 1u);
    EXPECT_EQ(board.services().at(ServiceId{"c", 1000}).planners, 2);
    EXPECT_TRUE(board.heard("coordinator"));
    EXPECT_TRUE(board.repeated_names().empty());
}

// Two clusters started alike on one bus: two processes named "c" are two entries, each with
// its own numbers, and the name is reported as repeated.
TEST(Status, BoardKeepsProcessesWithOneNameApart) {
    Bus bus("memq://", quiet());
    StatusBoard board(bus);
    envdesign::service_status_t s{};
    s.kind = "coordinator";
    s.sender = "c";
    s.started_utime = 2000;
    s.role = "standby";
    bus.publish(STATUS, s);
    s.started_utime = 1000;
    s.role = "active";
    bus.publish(STATUS, s);
    s.kind = "planner";
    s.sender = "p";
    s.role = "";
    bus.publish(STATUS, s);
    drain(bus);
    ASSERT_EQ(board.services().size(), 3u);
    EXPECT_EQ(board.services().at(ServiceId{"c", 1000}).role, "active");
    EXPECT_EQ(board.services().at(ServiceId{"c", 2000}).role, "standby");
    EXPECT_EQ(board.services().begin()->first, (ServiceId{"c", 1000})); // name, then start
    EXPECT_EQ(board.repeated_names(), (std::map<std::string, int>{{"c", 2}}));
}

} // namespace
} // namespace envdesign::bus
