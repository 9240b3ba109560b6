// envdesign-bridge under systemd (issue 11): with NOTIFY_SOCKET set it says READY=1 once its
// specs are loaded and it is on both buses, then feeds the watchdog from its main loop
// (WATCHDOG_USEC 200 ms: every 100 ms), and says STOPPING=1 on SIGTERM.

#include "harness.h"

#include "../support/notify_socket.h"

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

TEST(BridgeNotify, ReadyThenWatchdogThenStopping) {
    std::string dir = scratch("notify");
    NotifySocket socket(dir + "/notify.sock");
    std::vector<std::string> env = dds_env();
    for (const auto &e : socket.env(200'000))
        env.push_back(e);
    Process bridge({BIN + "/envdesign-bridge", "--problem", "restaurant=" + DRIFT_SPEC, "--domain",
                    "79", "--lcm-url", lcm_url(7779), "--name", "bridge/notify"},
                   env, dir + "/bridge.log");
    auto ready = socket.next(30s);
    ASSERT_TRUE(ready) << bridge.output();
    EXPECT_NE(ready->find("READY=1"), std::string::npos) << *ready;
    int watchdogs = 0;
    auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < 1s) {
        auto m = socket.next(300ms);
        ASSERT_TRUE(m) << "the watchdog stopped after " << watchdogs << "\n" << bridge.output();
        EXPECT_EQ(*m, "WATCHDOG=1");
        ++watchdogs;
    }
    EXPECT_GE(watchdogs, 4);
    bridge.signal(SIGTERM);
    EXPECT_TRUE(socket.until("STOPPING=1", 10s)) << bridge.output();
    EXPECT_EQ(bridge.wait(), 0) << bridge.output();
}

} // namespace
} // namespace envdesign::testing
