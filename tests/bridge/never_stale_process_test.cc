// The bridge is never stale (issue 11), with real processes over loopback: after a drift has
// had the barrier design evaluated, the mix drifts back slowly (100 arrivals/s, window 100),
// never `--threshold` away from the D of the design in force, so no re-evaluation is asked
// for; the re-weightings over the stored evaluations still bring back the design that is
// optimal for the final mix, published on ENVDESIGN_RESULT as "re-weighted".

#include "harness.h"

#include <algorithm>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

TEST(NeverStale, ReweighingFollowsASlowDriftBelowTheThreshold) {
    std::string dir = scratch("never-stale");
    Listener lcm(lcm_url(7768));
    auto bridge = start_bridge(dir, 68, 7768,
                               {"--estimator", "window:100", "--threshold", "0.3", "--rearm", "0.1",
                                "--min-samples", "50", "--holdoff", "20"});
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() >= 1; }, 30s)) << bridge->output();
    const std::vector<std::string> barrier{"barrier-00-01"};
    // To 0.1 serve-g1: a drift request has the barrier evaluated (planners).
    publish(dir, write_replay(dir + "/to-g2.csv", "task", booth_mix(200, 1)), 68,
            {"--rate", "1000"});
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 200 && m->design == barrier &&
                   m->state == envdesign::task_distribution_t::STATE_ARMED;
        },
        60s))
        << bridge->output();
    std::this_thread::sleep_for(500ms);
    std::size_t requests = lcm.requests().size();

    // Slowly back to 0.8 serve-g1, where no design is optimal (the spec's comment).
    publish(dir, write_replay(dir + "/back.csv", "task", booth_mix(100, 8)), 68, {"--rate", "100"});
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 300 && m->design.empty();
        },
        30s))
        << bridge->output();
    EXPECT_EQ(lcm.requests().size(), requests) << "a re-evaluation was asked for";
    auto results = lcm.results();
    EXPECT_TRUE(std::any_of(results.begin(), results.end(), [](const auto &r) {
        return r.message.change.find("re-weighted: design {barrier-00-01} -> {}") !=
               std::string::npos;
    })) << bridge->output();
    EXPECT_EQ(bridge->stop(), 0);
}

} // namespace
} // namespace envdesign::testing
