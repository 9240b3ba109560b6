// robot_behaviour EXPLAINING through the bridge, with real processes over loopback:
// envdesign-arrivals (DDS) -> envdesign-bridge (local re-design) -> ENVDESIGN_RESULT. The spec
// (data/restaurant-explaining.textproto, H = 1 + 0.9 + 0.81 = 2.71, explanation_cost 10):
//   D = 0.9 / 0.1, no design: G1 acts explicably (H e^2 + 0.75 * 7 = 25.27 against explaining
//     its two closed passages, H * 21 + 5.25 = 62.16), G2 explains (H * 21 + 6 = 62.91 against
//     H e^4 + 6 = 153.96): 29.038;
//   200 arrivals at 1:9 (window 100): barrier-00-01 (cost 30), both act explicably
//     (G2: H e^2 + 6 = 26.02 against one difference, H * 11 + 6 = 35.81), as the
//     self-contained run for the bridge's final D says.
// The explanations are on the wire: each task of the result says which option it takes and
// which differences it would tell.

#include "harness.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <regex>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

const std::string EXPLAINING_SPEC = SOURCE + "/tests/bridge/data/restaurant-explaining.textproto";

const envdesign::task_result_t &task(const envdesign::design_result_t &r, const std::string &n) {
    for (const auto &t : r.tasks)
        if (t.name == n)
            return t;
    throw std::runtime_error("no task " + n);
}

TEST(BridgeExplaining, OptionsAndExplanationsFollowTheDrift) {
    std::string dir = scratch("explaining");
    const int port = 7793, domain = 93;
    Listener lcm(lcm_url(port));
    Process bridge({BIN + "/envdesign-bridge",
                    "--problem",
                    "restaurant=" + EXPLAINING_SPEC,
                    "--domain",
                    std::to_string(domain),
                    "--lcm-url",
                    lcm_url(port),
                    "--name",
                    "bridge/test",
                    "--publish-hz",
                    "50",
                    "--estimator",
                    "window:100",
                    "--threshold",
                    "0.3",
                    "--rearm",
                    "0.1",
                    "--min-samples",
                    "50",
                    "--holdoff",
                    "20"},
                   dds_env(), dir + "/bridge.log");
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() >= 1; }, 30s)) << bridge.output();
    const double h = 1 + 0.9 + 0.81;
    {
        envdesign::design_result_t first = lcm.results().front().message;
        ASSERT_EQ(first.exit_code, 0) << first.error;
        EXPECT_TRUE(first.design.empty());
        EXPECT_NEAR(first.best.objective, 0.9 * (h * std::exp(2.0) + 5.25) + 0.1 * (21 * h + 6),
                    1e-9);
        EXPECT_NEAR(first.best.explanation, 0.1 * 20 * h, 1e-9);
        const auto &g1 = task(first, "serve-g1"), &g2 = task(first, "serve-g2");
        const std::vector<std::string> two{"-init (connected c00 c01)",
                                           "-init (connected c10 c11)"};
        EXPECT_TRUE(g1.has_explanation && g2.has_explanation);
        EXPECT_FALSE(g1.explained);
        EXPECT_TRUE(g2.explained);
        EXPECT_EQ(g1.explanation.differences, two);
        EXPECT_EQ(g2.explanation.differences, two);
        EXPECT_EQ(g2.ie, 1);
        EXPECT_EQ(g2.explicable_ie, std::exp(4.0));
        EXPECT_EQ(g2.plan, g2.explanation.robot_plan);
    }
    publish(dir, write_replay(dir + "/to-g2.csv", "task", booth_mix(200, 1)), domain,
            {"--rate", "1000"});
    const std::vector<std::string> barrier{"barrier-00-01"};
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 200 && m->design == barrier &&
                   m->state == envdesign::task_distribution_t::STATE_ARMED;
        },
        60s))
        << bridge.output();
    envdesign::design_result_t last = lcm.results().back().message;
    EXPECT_EQ(last.design, barrier);
    std::map<std::string, double> d;
    for (const auto &t : last.tasks) {
        d[t.name] = t.probability;
        EXPECT_TRUE(t.has_explanation);
        EXPECT_FALSE(t.explained) << t.name;
        EXPECT_EQ(t.explanation.differences, std::vector<std::string>{"-init (connected c10 c11)"});
    }
    EXPECT_LT(d.at("serve-g1"), 0.3);
    nlohmann::json want = self_contained(dir, EXPLAINING_SPEC, d);
    EXPECT_EQ(want.at("design"), nlohmann::json(barrier));
    EXPECT_NEAR(want.at("objective").get<double>(), last.best.objective, 1e-9);
    EXPECT_EQ(bridge.stop(), 0);
}

} // namespace
} // namespace envdesign::testing
