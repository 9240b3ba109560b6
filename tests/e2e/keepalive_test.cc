// Requests dropped when their client stops asking (issue 21, real processes): a client says
// every 2 s that it still waits (ENVDESIGN_KEEPALIVE); the coordinator drops a request it has
// not heard of for --client-timeout, so a killed client's never-ending search does not hold a
// planner, while a live client waiting longer than the timeout keeps its request.

#include "local_cluster.h"
#include "never_ending_spec.h"

#include "bus/log.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "spec/spec_bundle.h"

#include <envdesign/client/client.h>

#include <csignal>
#include <iostream>

namespace envdesign::e2e {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

class ClientKeepalive : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("envdesign-keepalive-" + std::to_string(getpid()));
        fs::remove_all(dir);
        spec = write_switches_spec(dir);
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir);
    }
    fs::path dir;
    std::string spec;
};

// `envdesign design --connect` with a search that never ends, SIGKILLed while its planner
// works: within the timeout the request is dropped, its job withdrawn (the planner holds
// nothing), and the next client's request has the planner. Before, the planner kept the job
// until --max-time-limit (an hour).
TEST_F(ClientKeepalive, AKilledClientsRequestIsDroppedAndItsPlannerFreed) {
    LocalCluster cluster(1, {"--client-timeout", "3"});
    HeartbeatTally tally(cluster.url());
    Process cli({binary("envdesign"), "design", spec, "--connect", cluster.url(), "--heuristic",
                 "blind", "--time-limit", "0"},
                (dir / "cli.log").string());
    ASSERT_TRUE(tally.until([&] { return tally.held() > 0; }, 20)) << cluster.logs();
    std::this_thread::sleep_for(std::chrono::seconds(4)); // alive past the timeout: kept
    ASSERT_EQ(cluster.coordinator().output().find("dropped"), std::string::npos) << cluster.logs();
    cli.signal(SIGKILL);
    cli.wait();
    auto killed = Clock::now();
    ASSERT_TRUE(wait_for_output(cluster.coordinator(), "dropped: nothing heard from its client"))
        << cluster.logs();
    double dropped = seconds_since(killed);
    EXPECT_TRUE(tally.until([&] { return tally.held() == 0; }, 2))
        << "the planner still holds the dropped request's job\n"
        << cluster.logs();
    double freed = seconds_since(killed);
    // The last keepalive came at most 2 s before the kill; the coordinator checks every 5 ms.
    EXPECT_LT(dropped, 3.5) << cluster.logs();
    client::Options options;
    options.give_up_after_s = 20;
    auto start = Clock::now();
    client::Result next = client::run_design_remote(
        source("examples/restaurant/c-two-tasks-t10.textproto"), cluster.url(), options);
    EXPECT_EQ(next.exit_code, 0) << next.error << cluster.logs();
    std::cout << "dropped " << dropped << " s after the kill, planner free after " << freed
              << " s; the next request took " << seconds_since(start) << " s\n";
}

// A live client whose request searches 8 s, beyond a 3 s timeout: its keepalives keep it;
// the search ends at its own limit.
TEST_F(ClientKeepalive, ALiveClientWaitingLongerThanTheTimeoutIsKept) {
    LocalCluster cluster(1, {"--client-timeout", "3"});
    client::Options options;
    options.heuristic = "blind";
    options.time_limit_s = 8;
    options.give_up_after_s = 30;
    auto start = Clock::now();
    client::Result result = client::run_design_remote(spec, cluster.url(), options);
    double took = seconds_since(start);
    EXPECT_EQ(result.exit_code, 4) << result.error << cluster.logs();
    EXPECT_GT(took, 7.5) << cluster.logs();
    EXPECT_EQ(cluster.coordinator().output().find("dropped"), std::string::npos) << cluster.logs();
}

// A keepalive from another process does not keep a request (with keys, the process that
// sent it is its client): only the signed sender of the request counts.
TEST_F(ClientKeepalive, AKeepaliveFromAnotherProcessDoesNotKeepARequest) {
    std::string key = (dir / "bus.key").string();
    std::ofstream(key) << "k1 " << std::string(64, '3') << "\n";
    fs::permissions(key, fs::perms::owner_read | fs::perms::owner_write);
    LocalCluster cluster(1, {"--client-timeout", "3"}, key);
    auto keys = std::make_shared<const bus::KeyRing>(bus::load_key_file(key));
    auto quiet = [] {
        return std::make_shared<spdlog::logger>("test",
                                                std::make_shared<spdlog::sinks::null_sink_mt>());
    };
    bus::Bus client(cluster.url(), quiet(), keys);
    bus::Bus other(cluster.url(), quiet(), keys);
    envdesign::design_request_t request{};
    request.utime = bus::now_utime();
    request.request_id = 7;
    request.sender = "gone";
    request.spec = spec::bundle_spec(spec);
    request.time_limit_s = 0;
    request.max_design_size = -1;
    request.heuristic = envdesign::design_request_t::HEURISTIC_BLIND;
    client.publish(bus::REQUEST, request);
    envdesign::keepalive_t keepalive{};
    keepalive.request_id = 7;
    keepalive.sender = "gone";
    auto start = Clock::now();
    while (seconds_since(start) < 8 &&
           cluster.coordinator().output().find("dropped:") == std::string::npos) {
        keepalive.utime = bus::now_utime();
        other.publish(bus::KEEPALIVE, keepalive);
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    EXPECT_NE(cluster.coordinator().output().find("request gone#7 | dropped"), std::string::npos)
        << cluster.logs();
    EXPECT_NE(cluster.coordinator().output().find("a keepalive from another process"),
              std::string::npos)
        << cluster.logs();
}

} // namespace
} // namespace envdesign::e2e
