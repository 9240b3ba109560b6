// The bridge core (common/bridge) in-process: scripted arrivals from an ArrivalQueue, a
// hand-set clock, LCM over memq://, no DDS and no other process. Each design the bridge
// publishes is checked against the exhaustive design search run here for the same D, and
// against the objectives in restaurant-drift.textproto's comment (38.143 for {} at 0.9
// serve-g1, 55.949 for {barrier-00-01} at 0.1).

#include "bridge/bridge.h"

#include "../bus/bus_test_support.h"
#include "bus/channels.h"
#include "cluster/coordinator.h"
#include "cluster/planner.h"
#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "envdesign/task_distribution_t.hpp"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace envdesign::bridge {
namespace {

using envdesign::task_distribution_t;

const std::string SPEC =
    std::string(ENVDESIGN_SOURCE_DIR) + "/tests/arrivals/data/restaurant-drift.textproto";
const std::string EXAMPLES = std::string(ENVDESIGN_SOURCE_DIR) + "/examples/restaurant/";
constexpr std::int64_t START_UTIME = 1'700'000'000'000'000;

struct Optimum {
    std::vector<std::string> design;
    double objective;
};

// The exhaustive search for the spec with P(serve-g1) = p: the independent answer.
Optimum exhaustive(double p) {
    design::DesignProblem problem = spec::load_design_problem(SPEC);
    for (auto &task : problem.tasks)
        task.probability = task.name == "serve-g1" ? p : 1 - p;
    design::LocalEvaluator evaluator(problem, 1);
    design::DesignSearchOptions options;
    options.method = design::SearchMethod::EXHAUSTIVE;
    design::DesignResult r = design::search_design(problem, evaluator, options);
    return {design::design_names(problem, r.best->ranked.configuration), r.best->objective.value};
}

double probability(const task_distribution_t &m, const std::string &task) {
    for (int i = 0; i < m.num_tasks; ++i)
        if (m.tasks[i] == task)
            return m.probabilities[i];
    return -1;
}

std::string read(const std::string &path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

BridgeConfig config(double threshold, Mode mode) {
    BridgeConfig c;
    c.instance = "bridge/test";
    c.problems = {{"restaurant", SPEC}};
    c.tracker.estimator = arrivals::parse_estimator_config("window:10");
    c.tracker.drift.threshold = threshold;
    c.tracker.drift.rearm_threshold = 0.05;
    c.tracker.drift.min_samples = 10;
    c.tracker.drift.holdoff_arrivals = 5;
    c.tracker.reweigh_interval_s = 0.1;
    c.mode = mode;
    c.publish_hz = 1000;
    c.reader_thread = false; // the test pumps
    return c;
}

std::unique_ptr<cluster::Coordinator> coordinator_on(bus::Bus &bus) {
    cluster::CoordinatorConfig c;
    c.instance = "coordinator";
    c.pool.planner_timeout_s = 0.5;
    c.pool.lost_after_s = 0.15;
    return std::make_unique<cluster::Coordinator>(bus, c);
}

std::unique_ptr<cluster::Planner> planner_on(bus::Bus &bus) {
    cluster::PlannerConfig p;
    p.instance = "planner-0";
    p.heartbeat_period_s = 0.05;
    return std::make_unique<cluster::Planner>(bus, p);
}

// One bridge on one memq bus, with what it publishes collected by the test's thread
// (subscribed before the bridge starts: memq drops what nobody subscribes to). With
// Mode::COORDINATOR a coordinator and a planner core share the bus and the test's thread.
class Rig {
public:
    explicit Rig(double threshold, Mode mode = Mode::LOCAL)
        : estimates_(bus_.subscribe<task_distribution_t>(
              bus::TASK_DISTRIBUTION, [this](const task_distribution_t &m) { last_estimate = m; })),
          requests_(bus_.subscribe<task_distribution_t>(
              bus::REEVALUATE, [this](const task_distribution_t &m) { requests.push_back(m); })),
          results_(bus_.subscribe<envdesign::design_result_t>(
              bus::RESULT,
              [this](const envdesign::design_result_t &m) {
                  // A repeat: the bridge sent a request again (its clock runs 20x fast here)
                  // and the coordinator answered it from what it had closed.
                  for (const auto &r : results)
                      if (r.request_id == m.request_id && r.client == m.client)
                          return;
                  results.push_back(m);
              })),
          coordinator_(mode == Mode::COORDINATOR ? coordinator_on(bus_) : nullptr),
          planner_(mode == Mode::COORDINATOR ? planner_on(bus_) : nullptr),
          bridge_(bus_, config(threshold, mode), queue_, clock_) {}

    // `pattern`: one arrival a character from site dock-1, '1' serve-g1, '2' serve-g2,
    // stamped `ahead_s` ahead of the bridge's wall clock.
    void arrive(const std::string &pattern, double ahead_s = 0) {
        for (char c : pattern)
            queue_.push({"restaurant", "dock-1", c == '1' ? "serve-g1" : "serve-g2", ++sequence_,
                         clock_.utime() + static_cast<std::int64_t>(ahead_s * 1e6), "", ""});
        bridge_.pump(0);
    }
    void push(arrivals::Arrival a) {
        queue_.push(std::move(a));
        bridge_.pump(0);
    }
    // Handles messages and ticks until `results` holds `count` and the bridge has taken as
    // many answers (the local redesigner publishes on its own thread, then answers the
    // bridge); the clock moves 0.2 s a round so that rate limits open.
    bool wait_results(std::size_t count) {
        auto done = [&] {
            BridgeStats s = bridge_.stats();
            return results.size() >= count &&
                   s.answers + s.reweigh_changes >= static_cast<long long>(count);
        };
        for (int round = 0; round < 3000 && !done(); ++round) {
            bus_.handle(std::chrono::milliseconds(10));
            clock_.advance(0.2);
            tick();
        }
        bus::drain(bus_);
        return done();
    }
    // A second of ticks and messages: whatever was due is out.
    void settle() {
        for (int i = 0; i < 5; ++i) {
            clock_.advance(0.2);
            tick();
            bus_.handle(std::chrono::milliseconds(20));
        }
        bus::drain(bus_);
    }
    Bridge &bridge() { return bridge_; }
    void tick() {
        bridge_.tick();
        if (coordinator_)
            coordinator_->tick();
        if (planner_)
            planner_->tick();
    }

    std::optional<task_distribution_t> last_estimate;
    std::vector<task_distribution_t> requests;
    std::vector<envdesign::design_result_t> results;

private:
    bus::Bus bus_{"memq://", bus::quiet()};
    arrivals::ArrivalQueue queue_;
    ManualClock clock_{START_UTIME};
    std::int64_t sequence_ = 0;
    bus::Subscription estimates_, requests_, results_;
    std::unique_ptr<cluster::Coordinator> coordinator_;
    std::unique_ptr<cluster::Planner> planner_;
    Bridge bridge_; // last: it publishes from its constructor on
};

TEST(BridgeCore, ScriptedDriftGivesTheKnownEstimateAndTheOptimalDesign) {
    Rig rig(0.3);
    ASSERT_TRUE(rig.wait_results(1));
    // The spec's D (0.9 serve-g1): no design, objective 38.143.
    Optimum at_09 = exhaustive(0.9);
    EXPECT_EQ(rig.results[0].design, at_09.design);
    EXPECT_TRUE(at_09.design.empty());
    EXPECT_NEAR(rig.results[0].best.objective, 38.143, 1e-3);
    EXPECT_NEAR(rig.results[0].best.objective, at_09.objective, 1e-9);
    ASSERT_EQ(rig.requests.size(), 1u);
    EXPECT_EQ(rig.requests[0].reason, task_distribution_t::REASON_INITIAL);

    // One serve-g1 in every ten: window:10 holds exactly 0.1 / 0.9, TV 0.8 from the spec's D.
    rig.arrive("1222222222");
    ASSERT_TRUE(rig.wait_results(2));
    ASSERT_EQ(rig.requests.size(), 2u);
    const task_distribution_t &drift = rig.requests[1];
    EXPECT_EQ(drift.reason, task_distribution_t::REASON_DRIFT);
    EXPECT_DOUBLE_EQ(probability(drift, "serve-g1"), 0.1);
    EXPECT_DOUBLE_EQ(probability(drift, "serve-g2"), 0.9);
    EXPECT_NEAR(drift.distance, 0.8, 1e-12);
    Optimum at_01 = exhaustive(0.1);
    EXPECT_EQ(at_01.design, std::vector<std::string>{"barrier-00-01"});
    EXPECT_EQ(rig.results[1].design, at_01.design);
    EXPECT_NEAR(rig.results[1].best.objective, 55.949, 1e-3);
    EXPECT_NEAR(rig.results[1].best.objective, at_01.objective, 1e-9);
    // A local re-design is explained as the coordinator's answers are (design/design_run.h).
    EXPECT_TRUE(rig.results[0].has_explanation);
    ASSERT_TRUE(rig.results[1].has_explanation);
    EXPECT_EQ(rig.results[1].explanation.num_tasks, 2);
    rig.settle();
    ASSERT_TRUE(rig.last_estimate);
    EXPECT_EQ(rig.last_estimate->estimated, 10);
    EXPECT_EQ(rig.last_estimate->design, at_01.design);
    EXPECT_NEAR(rig.last_estimate->objective, at_01.objective, 1e-9);
    EXPECT_EQ(rig.bridge().design("restaurant").design, at_01.design);
    EXPECT_EQ(rig.bridge().stats().answers, 2);
}

TEST(BridgeCore, ScriptedDriftThroughACoordinatorGivesTheOptimalDesign) {
    Rig rig(0.3, Mode::COORDINATOR);
    ASSERT_TRUE(rig.wait_results(1));
    Optimum at_09 = exhaustive(0.9), at_01 = exhaustive(0.1);
    const envdesign::design_result_t &initial = rig.results[0];
    EXPECT_EQ(initial.sender, "coordinator"); // the coordinator answered the bridge
    EXPECT_EQ(initial.client, "bridge/test");
    EXPECT_EQ(initial.design, at_09.design);
    EXPECT_NEAR(initial.best.objective, at_09.objective, 1e-9);
    rig.arrive("1222222222");
    ASSERT_TRUE(rig.wait_results(2));
    ASSERT_EQ(rig.requests.size(), 2u);
    EXPECT_EQ(rig.requests[1].reason, task_distribution_t::REASON_DRIFT);
    const envdesign::design_result_t &drift = rig.results[1];
    EXPECT_EQ(drift.sender, "coordinator");
    EXPECT_EQ(drift.design, at_01.design);
    EXPECT_NEAR(drift.best.objective, 55.949, 1e-3);
    EXPECT_NEAR(drift.best.objective, at_01.objective, 1e-9);
    rig.settle();
    ASSERT_TRUE(rig.last_estimate);
    EXPECT_EQ(rig.last_estimate->design, at_01.design);
    EXPECT_EQ(rig.bridge().stats().reweighs, 0); // the store is the coordinator's
}

// Far below the threshold (TV 0.8 < 0.95), the re-weighting for 0.1 serve-g1 needs the
// barrier evaluated, which the store lacks: the bridge asks for it at once instead of keeping
// the stale design until the estimate moves 0.95 (the soak saw 1.5 s to 72 s of staleness).
// Once stored, going back is a re-weighting again, with no request.
TEST(BridgeCore, AReweighingThatNeedsPlannersAsksForThemAtOnce) {
    Rig rig(0.95);
    ASSERT_TRUE(rig.wait_results(1));
    rig.arrive("1222222222");
    ASSERT_TRUE(rig.wait_results(2));
    ASSERT_EQ(rig.requests.size(), 2u);
    EXPECT_EQ(rig.requests[1].reason, task_distribution_t::REASON_DRIFT);
    Optimum at_01 = exhaustive(0.1);
    EXPECT_EQ(rig.results[1].design, at_01.design);
    EXPECT_NEAR(rig.results[1].best.objective, at_01.objective, 1e-9);
    EXPECT_GE(rig.bridge().stats().reweigh_planning, 1);

    rig.arrive("1111111112"); // 0.9 serve-g1 again: {} from the store
    ASSERT_TRUE(rig.wait_results(3));
    rig.settle();
    EXPECT_EQ(rig.requests.size(), 2u);
    EXPECT_EQ(rig.results[2].design, exhaustive(0.9).design);
    EXPECT_NE(rig.results[2].change.find("re-weighted"), std::string::npos);
}

TEST(BridgeCore, BelowTheThresholdReweighingBringsTheOptimalDesignWithoutARequest) {
    Rig rig(0.75);
    ASSERT_TRUE(rig.wait_results(1));
    rig.arrive("1222222222"); // TV 0.8 > 0.75: planners evaluate the barrier
    ASSERT_TRUE(rig.wait_results(2));
    ASSERT_EQ(rig.results[1].design, std::vector<std::string>{"barrier-00-01"});
    // Eight in ten serve-g1: TV 0.7 from the barrier's D, below the threshold; no request,
    // but the re-weighting over stored evaluations finds {} optimal again.
    rig.arrive("1111111122");
    ASSERT_TRUE(rig.wait_results(3));
    rig.settle();
    EXPECT_EQ(rig.requests.size(), 2u) << "a re-evaluation was asked for below the threshold";
    Optimum at_08 = exhaustive(0.8);
    EXPECT_TRUE(at_08.design.empty());
    EXPECT_EQ(rig.results[2].design, at_08.design);
    EXPECT_NEAR(rig.results[2].best.objective, at_08.objective, 1e-9);
    EXPECT_NE(rig.results[2].change.find("re-weighted"), std::string::npos)
        << rig.results[2].change;
    ASSERT_TRUE(rig.last_estimate);
    EXPECT_DOUBLE_EQ(probability(*rig.last_estimate, "serve-g1"), 0.8);
    EXPECT_EQ(rig.last_estimate->design, at_08.design);
    BridgeStats stats = rig.bridge().stats();
    EXPECT_GE(stats.reweigh_changes, 1);
    EXPECT_EQ(stats.requests, 2);
}

TEST(BridgeCore, BadSamplesAreCountedByKindAndSkewedClocksStillMoveTheEstimate) {
    Rig rig(0.9); // no drift request in this test
    ASSERT_TRUE(rig.wait_results(1));
    rig.push({"elsewhere", "dock-1", "serve-g1", 1, START_UTIME, "", ""});  // unknown problem
    rig.push({"restaurant", "dock-9", "", 1, START_UTIME, "", ""});         // empty task
    rig.push({"restaurant", "dock-2", "serve-g1", 0, START_UTIME, "", ""}); // bad sequence
    rig.push({"restaurant", "dock-2", "serve-g1", 1, 0, "", ""});           // bad timestamp
    rig.push({"restaurant", "dock-3", "serve-g2", 5, START_UTIME, "", ""});
    rig.push({"restaurant", "dock-3", "serve-g2", 5, START_UTIME, "", ""}); // duplicate
    // dock-1 runs 400 s fast (beyond --max-future 300): accepted, counted as skewed.
    rig.arrive("2222", 400);
    rig.settle();
    BridgeStats stats = rig.bridge().stats();
    using arrivals::Verdict;
    EXPECT_EQ(stats.intake.received, 10);
    EXPECT_EQ(stats.intake.count(Verdict::UNKNOWN_PROBLEM), 1);
    EXPECT_EQ(stats.intake.count(Verdict::EMPTY_TASK), 1);
    EXPECT_EQ(stats.intake.count(Verdict::BAD_SEQUENCE), 1);
    EXPECT_EQ(stats.intake.count(Verdict::BAD_TIMESTAMP), 1);
    EXPECT_EQ(stats.intake.count(Verdict::DUPLICATE), 1);
    EXPECT_EQ(stats.intake.count(Verdict::ACCEPTED), 5);
    EXPECT_EQ(stats.intake.clock_skewed, 4);
    EXPECT_NEAR(stats.intake.last_skew_s, 400, 1);
    ASSERT_TRUE(rig.last_estimate);
    EXPECT_EQ(rig.last_estimate->estimated, 5); // one serve-g2 of dock-3, four of dock-1
    EXPECT_DOUBLE_EQ(probability(*rig.last_estimate, "serve-g2"), 1.0);
    EXPECT_EQ(rig.requests.size(), 1u);
}

TEST(BridgeCore, ANewTaskWithItsProblemIsAddedByARedesign) {
    Rig rig(0.9);
    ASSERT_TRUE(rig.wait_results(1));
    // serve-g2's problems under a new name: the redesign must take it in as a third task.
    rig.push({"restaurant", "dock-1", "serve-g2-again", 1, START_UTIME,
              read(EXAMPLES + "serve-g2.pddl"), read(EXAMPLES + "serve-g2-human.pddl")});
    ASSERT_TRUE(rig.wait_results(2));
    ASSERT_EQ(rig.requests.size(), 2u);
    EXPECT_EQ(rig.requests[1].reason, task_distribution_t::REASON_NEW_TASK);
    EXPECT_EQ(rig.requests[1].new_tasks, std::vector<std::string>{"serve-g2-again"});
    const envdesign::design_result_t &r = rig.results[1];
    ASSERT_TRUE(r.has_design) << r.error;
    std::vector<std::string> names;
    for (const auto &t : r.tasks)
        names.push_back(t.name);
    EXPECT_EQ(names, (std::vector<std::string>{"serve-g1", "serve-g2", "serve-g2-again"}));
    // The new task is serve-g2 again: its IE and robot cost are serve-g2's.
    EXPECT_EQ(r.tasks[2].ie, r.tasks[1].ie);
    EXPECT_EQ(r.tasks[2].robot_cost, r.tasks[1].robot_cost);
}

// A bridge asking a coordinator over a lossy link: its requests reach the coordinator (on a
// bus of its own), and each result comes back only if `deliver` says so; the coordinator's
// progress never comes back, so the bridge hears silence until a result arrives.
class LossyLink {
public:
    explicit LossyLink(BridgeConfig c)
        : requests_(bridge_bus_.subscribe<envdesign::design_request_t>(
              bus::REQUEST,
              [this](const envdesign::design_request_t &m) {
                  ++requests_sent;
                  cluster_bus_.publish(bus::REQUEST, m);
              })),
          results_(cluster_bus_.subscribe<envdesign::design_result_t>(
              bus::RESULT,
              [this](const envdesign::design_result_t &m) {
                  answers.push_back(m);
                  if (deliver(m))
                      bridge_bus_.publish(bus::RESULT, m);
              })),
          keepalives_(bridge_bus_.subscribe<envdesign::keepalive_t>(
              bus::KEEPALIVE,
              [this](const envdesign::keepalive_t &k) { kept_alive.push_back(k.request_id); })),
          coordinator_(coordinator_on(cluster_bus_)), planner_(planner_on(cluster_bus_)),
          bridge(bridge_bus_, c, queue_, clock) {}

    // Handles both buses and ticks everyone until `done` (false after 3000 rounds).
    bool run_until(const std::function<bool()> &done, int rounds = 3000) {
        for (int round = 0; round < rounds && !done(); ++round) {
            bridge_bus_.handle(std::chrono::milliseconds(2));
            cluster_bus_.handle(std::chrono::milliseconds(2));
            coordinator_->tick();
            planner_->tick();
            bridge.tick();
        }
        bus::drain(bridge_bus_);
        return done();
    }
    void arrive_g2(int count) {
        for (int i = 0; i < count; ++i)
            queue_.push({"restaurant", "dock-1", "serve-g2", ++sequence_, clock.utime(), "", ""});
        bridge.pump(0);
    }
    void publish_to_bridge(const envdesign::design_result_t &m) {
        bridge_bus_.publish(bus::RESULT, m);
    }

    std::function<bool(const envdesign::design_result_t &)> deliver = [](const auto &) {
        return true;
    };
    std::vector<envdesign::design_result_t> answers; // every result the coordinator sent
    int requests_sent = 0;                           // by the bridge, repeats included
    std::vector<std::int64_t> kept_alive;            // request ids of the bridge's keepalives
    ManualClock clock{START_UTIME};

private:
    bus::Bus bridge_bus_{"memq://", bus::quiet()}, cluster_bus_{"memq://", bus::quiet()};
    arrivals::ArrivalQueue queue_;
    std::int64_t sequence_ = 0;
    bus::Subscription requests_, results_, keepalives_;
    std::unique_ptr<cluster::Coordinator> coordinator_;
    std::unique_ptr<cluster::Planner> planner_;

public:
    Bridge bridge; // last: it publishes from its constructor on
};

BridgeConfig lossy_config(double resend_after_s) {
    BridgeConfig c = config(0.3, Mode::COORDINATOR);
    c.tracker.drift.answer_timeout_s = 5;
    c.coordinator.resend_after_s = resend_after_s;
    return c;
}

// A request given up (answer_timeout_s) and asked again for the new D: the late answer to
// the first must not replace the design made for the second.
TEST(BridgeCore, ALateAnswerToARequestAskedAgainIsIgnored) {
    LossyLink link(lossy_config(1e6)); // no repeats: only the timeout acts
    link.deliver = [](const auto &) { return false; };
    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 1; })); // initial, held
    link.clock.advance(6); // the bridge gives up on it at the next arrival, asks for the new D
    link.arrive_g2(10);
    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 2; }));
    const auto &held = link.answers;
    ASSERT_GT(held[1].request_id, held[0].request_id);
    Optimum all_g2 = exhaustive(0), at_09 = exhaustive(0.9);
    EXPECT_EQ(held[0].design, at_09.design);
    EXPECT_EQ(held[1].design, all_g2.design);
    ASSERT_NE(all_g2.design, at_09.design);

    link.publish_to_bridge(held[1]);
    ASSERT_TRUE(link.run_until([&] { return link.bridge.stats().answers == 1; }));
    EXPECT_EQ(link.bridge.design("restaurant").design, all_g2.design);
    link.publish_to_bridge(held[0]); // the late one
    link.clock.advance(1);
    link.run_until([&] { return false; }, 100); // time for it to be taken, if it were
    EXPECT_EQ(link.bridge.stats().answers, 1);
    EXPECT_EQ(link.bridge.design("restaurant").design, all_g2.design);
}

// Lost after the last arrival: the initial request's answer, then a drift request's answer.
// With no arrival to notice it, the clock times each out (answer_timeout_s 5) and asks again.
TEST(BridgeCore, ARequestLostAfterTheLastArrivalIsAskedAgainOnTheClock) {
    LossyLink link(lossy_config(1e6)); // no repeats: only the timeout acts
    bool deliver = false;
    link.deliver = [&](const auto &) { return deliver; };
    Optimum all_g2 = exhaustive(0), at_09 = exhaustive(0.9);
    ASSERT_NE(all_g2.design, at_09.design);

    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 1; })); // lost
    deliver = true;
    link.clock.advance(4);
    link.run_until([&] { return link.requests_sent > 1; }, 100); // time to ask, if it did
    EXPECT_EQ(link.requests_sent, 1) << "asked again before the timeout";
    EXPECT_EQ(link.answers.size(), 1u);
    link.clock.advance(2);
    ASSERT_TRUE(link.run_until([&] { return link.bridge.stats().answers == 1; }));
    EXPECT_EQ(link.bridge.design("restaurant").design, at_09.design);

    deliver = false; // drift to all serve-g2; the request it makes is answered, then lost
    link.arrive_g2(10);
    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 3; }));
    deliver = true;
    link.clock.advance(6);
    ASSERT_TRUE(link.run_until([&] { return link.bridge.stats().answers == 2; }));
    EXPECT_EQ(link.answers.size(), 4u);
    EXPECT_EQ(link.bridge.design("restaurant").design, all_g2.design);
}

// Silence for resend_after_s (2): the same request again, long before the answer timeout;
// the coordinator answers the repeat from what it closed (the same request id, no search).
TEST(BridgeCore, ARequestTheCoordinatorIsSilentAboutIsSentAgain) {
    LossyLink link(lossy_config(2));
    bool deliver = false;
    link.deliver = [&](const auto &) { return deliver; };
    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 1; })); // lost
    EXPECT_EQ(link.requests_sent, 1);
    deliver = true;
    link.clock.advance(1.9);
    link.run_until([&] { return false; }, 100);
    EXPECT_EQ(link.requests_sent, 1) << "sent again before 2 s of silence";
    link.clock.advance(0.2);
    ASSERT_TRUE(link.run_until([&] { return link.bridge.stats().answers == 1; }));
    EXPECT_EQ(link.requests_sent, 2);
    ASSERT_EQ(link.answers.size(), 2u);
    EXPECT_EQ(link.answers[1].request_id, link.answers[0].request_id);
    EXPECT_EQ(link.answers[1].counters.planner_runs, link.answers[0].counters.planner_runs);
    EXPECT_EQ(link.bridge.design("restaurant").design, exhaustive(0.9).design);
    EXPECT_EQ(link.bridge.stats().requests, 1); // one request, sent twice
}

// While it waits for a result the bridge says so every 2 s on its clock (the coordinator
// drops a request whose client went silent), for the request it waits for.
TEST(BridgeCore, APendingRequestIsKeptAliveOnTheClock) {
    LossyLink link(lossy_config(1e6)); // no repeats: only keepalives say it still waits
    link.deliver = [](const auto &) { return false; };
    ASSERT_TRUE(link.run_until([&] { return link.answers.size() == 1; })); // held
    link.run_until([&] { return false; }, 50);
    EXPECT_TRUE(link.kept_alive.empty()) << "before 2 s";
    link.clock.advance(2.1);
    ASSERT_TRUE(link.run_until([&] { return !link.kept_alive.empty(); }));
    EXPECT_EQ(link.kept_alive[0], link.answers[0].request_id);
    EXPECT_EQ(link.requests_sent, 1);
}

} // namespace
} // namespace envdesign::bridge
