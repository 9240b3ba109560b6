// Hostile traffic against real service processes (issue 10, the crash and memory findings;
// authentication is tested on its own): a deep JSON spec must not crash the coordinator,
// forged spec chunks claiming huge specs must not grow a planner.

#include "local_cluster.h"

#include "bus/codec.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/spec_chunk_t.hpp"

#include <envdesign/client/client.h>

#include <fstream>

namespace envdesign::e2e {
namespace {

const char *RESTAURANT = "examples/restaurant/c-two-tasks-t10.textproto";

// Resident memory of process `pid` in KiB (/proc/PID/status, VmRSS).
long resident_kib(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string key;
    long value = -1;
    while (status >> key) {
        if (key == "VmRSS:") {
            status >> value;
            break;
        }
        status.ignore(1 << 20, '\n');
    }
    return value;
}

client::Result design(const LocalCluster &cluster) {
    client::Options options;
    options.give_up_after_s = 10;
    return client::run_design_remote(source(RESTAURANT), cluster.url(), options);
}

TEST(Hostile, DeepJsonRequestIsBadInputAndTheCoordinatorLives) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    std::optional<envdesign::design_result_t> answer;
    auto sub = bus.subscribe<envdesign::design_result_t>(bus::RESULT,
                                                         [&](const envdesign::design_result_t &r) {
                                                             if (r.request_id == 77)
                                                                 answer = r;
                                                         });
    envdesign::design_request_t request{};
    request.request_id = 77;
    request.sender = "attacker";
    request.spec.name = "deep.json";
    request.spec.text = "{\"task\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}";
    request.time_limit_s = -1;
    request.max_design_size = -1;
    bus.publish(bus::REQUEST, request);
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!answer && std::chrono::steady_clock::now() < until)
        bus.handle(std::chrono::milliseconds(50));
    ASSERT_TRUE(answer) << cluster.logs();
    EXPECT_EQ(answer->exit_code, 2);
    EXPECT_NE(answer->error.find("deep.json:1:109: error:"), std::string::npos) << answer->error;
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_EQ(design(cluster).exit_code, 0) << cluster.logs();
}

envdesign::spec_chunk_t last_chunk_of(int number, std::int32_t claimed_bytes) {
    envdesign::spec_chunk_t c{};
    c.sender = "attacker";
    c.spec_hash = std::string(64, 'b');
    c.spec_hash.replace(0, std::to_string(number).size(), std::to_string(number));
    c.total_bytes = claimed_bytes;
    c.num_chunks = static_cast<std::int16_t>((claimed_bytes + 31'999) / 32'000);
    c.chunk_index = static_cast<std::int16_t>(c.num_chunks - 1);
    c.num_bytes = static_cast<std::int16_t>(claimed_bytes - c.chunk_index * 32'000);
    c.data.assign(static_cast<std::size_t>(c.num_bytes), 'x');
    return c;
}

// Two forged chunks of ~213 bytes claiming 1 GB each took a planner from 9 MB to 2 GB.
// Now: chunks of specs beyond the limit are refused, and within it only what arrived is held.
TEST(Hostile, ChunkBombLeavesThePlannerSmall) {
    LocalCluster cluster(1);
    pid_t planner = cluster.planner(0).pid();
    long before = resident_kib(planner);
    ASSERT_GT(before, 0);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    bus.publish(bus::SPEC, last_chunk_of(1, 31'249 * 32'000 + 100)); // ~1 GB
    bus.publish(bus::SPEC, last_chunk_of(2, 31'249 * 32'000 + 100));
    for (int n = 3; n < 200; ++n) // within the default 16 MiB each
        bus.publish(bus::SPEC, last_chunk_of(n, 500 * 32'000 + 100));
    bus.handle(std::chrono::milliseconds(1000));
    long after = resident_kib(planner);
    EXPECT_LT(after - before, 50 * 1024)
        << "planner grew from " << before << " to " << after << " KiB";
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_EQ(design(cluster).exit_code, 0) << cluster.logs();
}

// A string length of INT_MIN in a message: lcm-gen 1.3.1's decoder overflowed and read
// gigabytes past the datagram (found by the planner fuzz target). Now it is a malformed
// message: counted and dropped, by the coordinator and a planner alike.
TEST(Hostile, NegativeStringLengthIsMalformedNotACrash) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    envdesign::job_t job{};
    job.sender = "coordinator";
    job.planner = "planner-0";
    envdesign::design_request_t request{};
    request.request_id = 5;
    request.sender = "attacker";
    // Fingerprint (8), utime (8), request_id (8), then the sender's length.
    auto forged = [](std::string bytes) { return bytes.replace(24, 4, "\x80\0\0\0", 4); };
    std::string bad_job = forged(bus::encode_message(job));
    std::string bad_request = forged(bus::encode_message(request));
    bus.publish_raw(bus::JOB, bad_job.data(), static_cast<int>(bad_job.size()));
    bus.publish_raw(bus::REQUEST, bad_request.data(), static_cast<int>(bad_request.size()));
    bus.handle(std::chrono::milliseconds(500));
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_EQ(design(cluster).exit_code, 0) << cluster.logs();
}

} // namespace
} // namespace envdesign::e2e
