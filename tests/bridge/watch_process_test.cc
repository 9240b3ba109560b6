// `envdesign watch` shows the bridge's task distribution estimates as they pass (issue 13):
// real processes, envdesign-arrivals (DDS) -> envdesign-bridge -> LCM -> envdesign watch.

#include "harness.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

// 100 arrivals of the 9:1 mix in a window of 100: the watcher's last distribution line for
// "restaurant" says exactly 0.9 / 0.1, from 100 samples; in text a distribution is one line.
TEST(WatchBridge, PrintsTheDistributionEstimates) {
    std::string dir = scratch("watch");
    auto bridge = start_bridge(dir, 80, 7780, {"--estimator", "window:100"});
    std::string out = dir + "/watch.out", text_out = dir + "/watch.txt";
    Process json_watch({"/bin/bash", "-c",
                        "exec " + BIN +
                            "/envdesign watch --json --status --seconds 60 --lcm-url '" +
                            lcm_url(7780) + "' > " + out},
                       dir + "/watch.log");
    Process text_watch({"/bin/bash", "-c",
                        "exec " + BIN + "/envdesign watch --status --seconds 60 --lcm-url '" +
                            lcm_url(7780) + "' > " + text_out},
                       dir + "/watch-text.log");
    // Both listen once they print the bridge's status (1/s), before any arrival is sent.
    for (const auto &file : {out, text_out}) {
        bool listening = false;
        for (int i = 0; i < 400 && !listening; ++i) {
            std::ifstream in(file);
            std::stringstream all;
            all << in.rdbuf();
            listening = all.str().find("status") != std::string::npos;
            std::this_thread::sleep_for(50ms);
        }
        ASSERT_TRUE(listening) << file << "\n" << bridge->output();
    }
    std::string replay = write_replay(dir + "/mix.csv", "task", booth_mix(100, 9));
    publish(dir, replay, 80, {"--rate", "2000"});
    // The bridge publishes each estimate at once (--publish-hz 50) and once a second idle:
    // wait until the JSON watcher printed the one of all 100 samples (seconds under load).
    auto heard_all = [&] {
        std::ifstream in(out);
        for (std::string line; std::getline(in, line);) {
            auto message = nlohmann::json::parse(line, nullptr, false);
            if (!message.is_discarded() && message.value("kind", "") == "distribution" &&
                message.value("samples", 0.0) == 100)
                return true;
        }
        return false;
    };
    for (int i = 0; i < 600 && !heard_all(); ++i)
        std::this_thread::sleep_for(50ms);
    std::this_thread::sleep_for(500ms); // the text watcher heard the same message
    json_watch.signal(SIGINT);
    text_watch.signal(SIGINT);
    EXPECT_EQ(json_watch.wait(10s), std::optional<int>(0)) << json_watch.output();
    EXPECT_EQ(text_watch.wait(10s), std::optional<int>(0)) << text_watch.output();
    EXPECT_TRUE(bridge->running()) << bridge->output();

    std::ifstream in(out);
    nlohmann::json last;
    int distributions = 0;
    for (std::string line; std::getline(in, line);) {
        auto message = nlohmann::json::parse(line, nullptr, false);
        ASSERT_FALSE(message.is_discarded()) << line;
        if (message["kind"] != "distribution")
            continue;
        ++distributions;
        last = message;
    }
    ASSERT_GT(distributions, 0) << bridge->output();
    EXPECT_EQ(last["channel"], "ENVDESIGN_TASK_DISTRIBUTION");
    EXPECT_EQ(last["problem_id"], "restaurant");
    EXPECT_EQ(last["bridge"], "bridge/test");
    EXPECT_EQ(last["estimator"], "window:100");
    EXPECT_DOUBLE_EQ(last["samples"].get<double>(), 100);
    EXPECT_NEAR(last["probabilities"]["serve-g1"].get<double>(), 0.9, 1e-12) << last;
    EXPECT_NEAR(last["probabilities"]["serve-g2"].get<double>(), 0.1, 1e-12) << last;

    std::ifstream text_in(text_out);
    std::stringstream text;
    text << text_in.rdbuf();
    EXPECT_NE(text.str().find("distribution restaurant: serve-g1 0.900, serve-g2 0.100 (100 "
                              "samples;"),
              std::string::npos)
        << text.str();
    EXPECT_EQ(bridge->stop(), 0);
}

} // namespace
} // namespace envdesign::testing
