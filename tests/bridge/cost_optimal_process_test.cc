// The bridge with a robot that is not an explicable planner (issue 14, robot_behaviour:
// COST_OPTIMAL): the design it publishes at start is the one for the worst cost-optimal plan
// (tests/e2e/data/cost-optimal/two-ways.textproto: take the hop away, objective 6, where an
// explicable robot would need no design), evaluated through the coordinator and a planner;
// when the arrivals drift to the other task, the coordinator answers from the evaluations
// it stored (their optimal actions included): no design.

#include "harness.h"

#include <cmath>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

const std::string TWO_WAYS = SOURCE + "/tests/e2e/data/cost-optimal/two-ways.textproto";

TEST(CostOptimalBridge, PublishesTheWorstCaseDesignAndFollowsADrift) {
    std::string dir = scratch("cost-optimal");
    const int port = 7791, domain = 91;
    Listener lcm(lcm_url(port));
    Process coordinator(
        {BIN + "/envdesign-coordinator", "--lcm-url", lcm_url(port), "--name", "coordinator"}, {},
        dir + "/coordinator.log");
    Process planner({BIN + "/envdesign-planner", "--lcm-url", lcm_url(port), "--name", "planner-0",
                     "--heartbeat", "0.1"},
                    {}, dir + "/planner.log");
    Process bridge({BIN + "/envdesign-bridge", "--problem", "restaurant=" + TWO_WAYS, "--domain",
                    std::to_string(domain), "--lcm-url", lcm_url(port), "--name", "bridge/test",
                    "--publish-hz", "50", "--redesign", "coordinator"},
                   dds_env(), dir + "/bridge.log");
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() >= 1; }, 30s)) << bridge.output();
    auto first = lcm.results().front().message;
    EXPECT_EQ(first.exit_code, 0) << first.error;
    EXPECT_EQ(first.design, std::vector<std::string>{"no-hop"});
    EXPECT_NEAR(first.best.objective, 6.0, 1e-9);
    EXPECT_NEAR(first.baseline.objective, 0.9 * std::exp(3.0) + 0.1, 1e-9);

    // Nearly everyone goes to n1 now: 0.1 * e^3 + 0.9 = 2.91 beats 6, no design.
    std::vector<std::string> rows;
    for (int i = 0; i < 100; ++i)
        rows.push_back(i % 10 == 0 ? "to-n2" : "to-n1");
    publish(dir, write_replay(dir + "/drift.csv", "task", rows), domain, {"--rate", "1000"});
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 100 && m->design.empty() &&
                   m->state == envdesign::task_distribution_t::STATE_ARMED;
        },
        60s))
        << bridge.output();
    auto last = lcm.results().back().message;
    EXPECT_EQ(last.exit_code, 0) << last.error;
    EXPECT_TRUE(last.design.empty());
    EXPECT_LT(last.best.objective, 6.0); // about 0.1 * e^3 + 0.9, as the estimate has it
    EXPECT_EQ(bridge.stop(), 0);
}

} // namespace
} // namespace envdesign::testing
