// The scripted drift with real processes over loopback: envdesign-arrivals (DDS) ->
// envdesign-bridge -> the re-evaluation (in the bridge, or envdesign-coordinator with a
// planner) -> ENVDESIGN_RESULT. 200 arrivals at 9:1 for serve-g1, then 200 at 1:9: the design
// flips from none to barrier-00-01, the design a self-contained `envdesign design` gives for
// the final D, and flips once.

#include "harness.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <regex>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

const std::vector<std::string> BRIDGE_FLAGS = {"--estimator", "window:100", "--threshold",   "0.3",
                                               "--rearm",     "0.1",        "--min-samples", "50",
                                               "--holdoff",   "20"};

std::map<std::string, double> distribution(const envdesign::design_result_t &r) {
    std::map<std::string, double> d;
    for (const auto &t : r.tasks)
        d[t.name] = t.probability;
    return d;
}

// Runs the drift against a started bridge and checks the results it causes.
void run_drift(const std::string &dir, Listener &lcm, Process &bridge, int domain) {
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() >= 1; }, 30s))
        << bridge.output(); // the design for the spec's D
    std::vector<std::string> rows = booth_mix(200, 9);
    for (const auto &r : booth_mix(200, 1))
        rows.push_back(r);
    publish(dir, write_replay(dir + "/drift.csv", "task", rows), domain, {"--rate", "1000"});
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 400 &&
                   m->state == envdesign::task_distribution_t::STATE_ARMED &&
                   lcm.results().size() == lcm.requests().size();
        },
        60s))
        << bridge.output();
    std::this_thread::sleep_for(500ms); // nothing more may come

    auto requests = lcm.requests();
    auto results = lcm.results();
    ASSERT_EQ(results.size(), requests.size()) << bridge.output();
    ASSERT_GE(results.size(), 2u);
    EXPECT_EQ(requests[0].message.reason, envdesign::task_distribution_t::REASON_INITIAL);
    std::vector<std::vector<std::string>> designs;
    int flips = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const auto &r = results[i].message;
        EXPECT_EQ(r.client, "bridge/test");
        EXPECT_EQ(r.exit_code, 0) << r.error;
        EXPECT_EQ(r.request_id, requests[i].message.request_id);
        if (i > 0) {
            EXPECT_EQ(requests[i].message.reason, envdesign::task_distribution_t::REASON_DRIFT);
            EXPECT_GE(requests[i].message.distance, 0.3);
            flips += r.design != designs.back();
            // ENVDESIGN_RESULT says what changed and why.
            std::string what =
                r.design != designs.back() ? "design {} -> {barrier-00-01}" : " unchanged";
            EXPECT_NE(r.change.find(what), std::string::npos) << r.change;
            EXPECT_NE(r.change.find("drift: D {serve-g1: "), std::string::npos) << r.change;
        }
        designs.push_back(r.design);
    }
    EXPECT_EQ(designs.front(), std::vector<std::string>{});
    EXPECT_EQ(designs.back(), std::vector<std::string>{"barrier-00-01"});
    EXPECT_EQ(flips, 1) << "the design flapped";
    EXPECT_LE(results.size(), 4u); // 0.9 -> ~0.6 -> ~0.3: two or three re-evaluations

    // The final design is the self-contained run's for the final D.
    auto final_d = distribution(results.back().message);
    EXPECT_LT(final_d.at("serve-g1"), 0.7);
    EXPECT_EQ(self_contained(dir, DRIFT_SPEC, final_d).at("design").get<std::vector<std::string>>(),
              designs.back());
    auto estimate = *lcm.last_estimate("restaurant");
    EXPECT_EQ(estimate.design, designs.back());
    EXPECT_NE(estimate.last_change.find("barrier-00-01"), std::string::npos);
}

TEST(Drift, FlipsOnceWithLocalRedesign) {
    std::string dir = scratch("drift-local");
    Listener lcm(lcm_url(7764));
    std::vector<std::string> flags = BRIDGE_FLAGS;
    auto bridge = start_bridge(dir, 64, 7764, flags);
    run_drift(dir, lcm, *bridge, 64);
    // Re-weighting: the bridge logs no planner run for a re-evaluation it had stored.
    EXPECT_EQ(bridge->stop(), 0);
}

TEST(Drift, FlipsOnceThroughTheCoordinator) {
    std::string dir = scratch("drift-coordinator");
    Listener lcm(lcm_url(7765));
    Process coordinator({BIN + "/envdesign-coordinator", "--lcm-url", lcm_url(7765), "--name",
                         "coordinator", "--planner-timeout", "0.5"},
                        {}, dir + "/coordinator.log");
    Process planner({BIN + "/envdesign-planner", "--lcm-url", lcm_url(7765), "--name", "planner-0",
                     "--heartbeat", "0.1"},
                    {}, dir + "/planner.log");
    std::vector<std::string> flags = BRIDGE_FLAGS;
    flags.insert(flags.end(), {"--redesign", "coordinator"});
    auto bridge = start_bridge(dir, 65, 7765, flags);
    run_drift(dir, lcm, *bridge, 65);
    for (const auto &r : lcm.results())
        EXPECT_EQ(r.message.sender, "coordinator");
    EXPECT_EQ(bridge->stop(), 0);
    EXPECT_EQ(coordinator.stop(), 0) << coordinator.output();
}

} // namespace
} // namespace envdesign::testing
