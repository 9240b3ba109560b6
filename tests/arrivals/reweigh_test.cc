// The bridge is never stale (issue 11): every change of the estimate is re-weighed over the
// stored evaluations (Redesigner::reweigh, no planner), and the design in force follows it;
// only work that needs planners waits for the drift threshold. Driven by direct calls, as
// the bridge drives them: ArrivalTracker -> reweighs_due -> Redesigner::reweigh ->
// ArrivalTracker::reweighed, and the drift requests -> Redesigner::redesign -> answered.

#include "arrivals/redesign.h"
#include "arrivals/tracker.h"
#include "restaurant_drift.h"

#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <memory>

namespace envdesign::arrivals {
namespace {

constexpr double ARRIVAL_S = 0.01; // 100 arrivals per second

TrackerConfig bridge_config() {
    TrackerConfig c;
    c.estimator = parse_estimator_config("window:200");
    c.drift.threshold = 0.2;
    c.drift.rearm_threshold = 0.1;
    c.drift.min_samples = 50;
    c.drift.holdoff_arrivals = 20;
    c.reweigh_interval_s = 0.1;
    return c;
}

// The bridge's loop over one problem, synchronous: what it did, counted.
struct Bridge {
    ArrivalTracker tracker{bridge_config()};
    std::unique_ptr<Redesigner> owned; // not movable: the evaluators hold its store
    Redesigner &redesigner;
    double now = 0;
    int64_t sequence = 0;
    long long drift_requests = 0;
    long long planner_runs = 0; // by the drift path's redesigns (a reweigh never plans)
    long long design_changes = 0;

    explicit Bridge(std::unique_ptr<Redesigner> r) : owned(std::move(r)), redesigner(*owned) {
        tracker.add_problem("restaurant", redesigner.distribution());
    }
    std::vector<std::string> design() const {
        return design::design_names(redesigner.problem(),
                                    redesigner.current()->ranked.configuration);
    }
    void arrive(const std::string &task, int64_t utime = NOW_UTIME) {
        now += ARRIVAL_S;
        Outcome o = tracker.receive({"restaurant", "site", task, ++sequence, utime, "", ""}, now,
                                    NOW_UTIME);
        if (o.request) {
            ++drift_requests;
            Redesign r = redesigner.redesign(o.request->estimate, {});
            planner_runs += r.change.planner_runs;
            design_changes += r.change.changed;
            tracker.answered("restaurant", redesigner.distribution(), now);
        }
        tick();
    }
    void tick() {
        for (const Request &request : tracker.reweighs_due(now))
            if (auto r = redesigner.reweigh(request.estimate)) {
                design_changes += r->change.changed;
                tracker.reweighed("restaurant", redesigner.distribution());
            }
    }
    // `n` arrivals, serve-g1 for the first `g1_count` of every 200.
    void replay(int n, int g1_count) {
        for (int i = 0; i < n; ++i)
            arrive(i % 200 < g1_count ? "serve-g1" : "serve-g2");
        now += 1; // the rate limit held the last ones back: the bridge's tick() takes them
        tick();
    }
    Distribution estimate() const { return tracker.status("restaurant")->estimate; }
};

// The case: the replay ends with the mix 0.165 (TV) from the D of the design in force,
// below the drift threshold 0.2, and another design is optimal there. The store holds what
// is needed (both sides were evaluated before), so the design in force becomes the optimal
// one with no drift request and no planner run. The old bridge kept {} until TV 0.2.
TEST(Reweigh, TheDesignFollowsAMixBelowTheThresholdWithoutPlanners) {
    auto r = std::make_unique<Redesigner>(spec::load_design_problem(RESTAURANT_DRIFT),
                                          RedesignOptions{});
    r->redesign(g1(0.1), {});
    r->redesign(g1(0.9), {}); // the design in force: {}, for 0.9
    Bridge bridge(std::move(r));
    ASSERT_EQ(bridge.design(), std::vector<std::string>{});
    bridge.replay(600, 147); // window 200: 147 / 200 = 0.735 serve-g1, TV 0.165 from 0.9

    Distribution final_d = bridge.estimate();
    EXPECT_NEAR(final_d.at("serve-g1"), 0.735, 1e-12);
    design::DesignResult expected = fresh(final_d);
    ASSERT_TRUE(expected.optimal);
    auto expected_names =
        design::design_names(bridge.redesigner.problem(), expected.best->ranked.configuration);
    ASSERT_NE(expected_names, std::vector<std::string>{}); // the case is one that matters
    EXPECT_EQ(bridge.design(), expected_names);
    EXPECT_NEAR(bridge.redesigner.current()->objective.value, expected.best->objective.value, 1e-9);
    EXPECT_EQ(bridge.drift_requests, 0);
    EXPECT_EQ(bridge.planner_runs, 0);
    EXPECT_GE(bridge.design_changes, 1);
    EXPECT_EQ(bridge.redesigner.reweighs_needing_planning(), 0);
    EXPECT_LT(bridge.tracker.status("restaurant")->distance, 0.1); // the reference followed
}

// Only {} for 0.9 was ever evaluated: a re-weighting for a D where a barrier may win needs
// evaluations the store lacks, so it changes nothing (and plans nothing); the planners are
// asked for only when the drift detector passes its threshold, and then the design is the
// optimal one.
TEST(Reweigh, MissingEvaluationsWaitForTheDriftThreshold) {
    auto r = std::make_unique<Redesigner>(spec::load_design_problem(RESTAURANT_DRIFT),
                                          RedesignOptions{});
    r->redesign(g1(0.9), {});
    Bridge bridge(std::move(r));
    // Straight to the far side: a reweigh alone cannot prove the barrier's design.
    EXPECT_FALSE(bridge.redesigner.reweigh(g1(0.1)));
    EXPECT_EQ(bridge.redesigner.distribution(), g1(0.9)); // nothing changed
    EXPECT_EQ(bridge.design(), std::vector<std::string>{});
    EXPECT_EQ(bridge.redesigner.reweighs_needing_planning(), 1);

    bridge.replay(400, 60); // to 0.3 serve-g1
    EXPECT_GE(bridge.drift_requests, 1);
    EXPECT_GT(bridge.planner_runs, 0);
    EXPECT_GT(bridge.redesigner.reweighs_needing_planning(), 1);
    design::DesignResult expected = fresh(bridge.estimate());
    EXPECT_EQ(bridge.redesigner.current()->ranked.configuration,
              expected.best->ranked.configuration);
}

// The tracker asks for a re-weighting only when the estimate changed, at most once per
// interval, and not while a request is pending.
TEST(Reweigh, DueOnChangeRateLimitedNotWhilePending) {
    TrackerConfig c = bridge_config();
    c.drift.min_samples = 3; // no drift request from the first two arrivals
    c.drift.holdoff_arrivals = 1;
    ArrivalTracker tracker(c);
    tracker.add_problem("p", {{"a", 0.5}, {"b", 0.5}});
    int64_t seq = 0;
    auto arrive = [&](const std::string &task, double now) {
        return tracker.receive({"p", "s", task, ++seq, NOW_UTIME, "", ""}, now, NOW_UTIME);
    };
    EXPECT_TRUE(tracker.reweighs_due(0).empty()); // nothing arrived
    arrive("a", 0.0);
    arrive("b", 0.0);
    auto due = tracker.reweighs_due(0.0);
    ASSERT_EQ(due.size(), 1u);
    EXPECT_EQ(due[0].reason, Reason::REWEIGH);
    EXPECT_EQ(due[0].estimate, (Distribution{{"a", 0.5}, {"b", 0.5}}));
    EXPECT_TRUE(tracker.reweighs_due(1.0).empty()); // no change since
    arrive("a", 1.0);
    EXPECT_EQ(tracker.reweighs_due(1.0).size(), 1u);
    arrive("b", 1.05);
    EXPECT_TRUE(tracker.reweighs_due(1.05).empty()); // within 0.1 s
    EXPECT_EQ(tracker.reweighs_due(1.1).size(), 1u);
    // Drift to a pending request: no re-weighting until it is answered.
    std::optional<Request> pending;
    for (int i = 0; i < 20 && !pending; ++i)
        pending = arrive("a", 2.0).request;
    ASSERT_TRUE(pending);
    EXPECT_TRUE(tracker.reweighs_due(3.0).empty());
    tracker.reweighed("p", {{"a", 1}}); // ignored while pending
    EXPECT_EQ(tracker.status("p")->state, DriftState::PENDING);
    tracker.answered("p", pending->estimate, 3.0);
    EXPECT_EQ(tracker.reweighs_due(3.0).size(), 1u);
    EXPECT_EQ(tracker.status("p")->reweighs, 4);
    // The estimate moved on while that re-weighting ran: the reference moves, the detector
    // stays armed (answered() would hold it for 30 s: a stale design at 1000 arrivals/s).
    tracker.reweighed("p", {{"a", 0.5}, {"b", 0.5}});
    EXPECT_EQ(tracker.status("p")->state, DriftState::ARMED);
    EXPECT_EQ(tracker.status("p")->reference, (Distribution{{"a", 0.5}, {"b", 0.5}}));
    EXPECT_FALSE(arrive("a", 4.0).request == std::nullopt); // far from it: drift at once
}

// Arrivals stamped 10 minutes ahead of the bridge's clock (beyond --max-future 300 s) still
// move the estimate, from their order, and the skew counter shows them.
TEST(Reweigh, ArrivalsFromASkewedClockStillMoveTheEstimate) {
    Bridge bridge(std::make_unique<Redesigner>(spec::load_design_problem(RESTAURANT_DRIFT),
                                               RedesignOptions{}));
    const int64_t ten_minutes = 600'000'000;
    for (int i = 0; i < 10; ++i)
        bridge.tracker.receive(
            {"restaurant", "fast-clock", "serve-g2", i + 1, NOW_UTIME + ten_minutes, "", ""}, 0,
            NOW_UTIME);
    auto s = bridge.tracker.status("restaurant");
    EXPECT_EQ(s->estimated, 10);
    EXPECT_EQ(s->estimate, (Distribution{{"serve-g2", 1}}));
    EXPECT_EQ(bridge.tracker.counters().clock_skewed, 10);
    EXPECT_NEAR(bridge.tracker.counters().last_skew_s, 600, 1e-6);
    EXPECT_EQ(bridge.tracker.counters().count(Verdict::BAD_TIMESTAMP), 0);
}

} // namespace
} // namespace envdesign::arrivals
