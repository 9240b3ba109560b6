// The bridge's state: estimates per problem, unknown and new tasks, scripted drift.

#include "arrivals/tracker.h"
#include "restaurant_drift.h"

#include <gtest/gtest.h>

namespace envdesign::arrivals {
namespace {

TrackerConfig tracker_config(const std::string &estimator = "window:10") {
    TrackerConfig c;
    c.estimator = parse_estimator_config(estimator);
    c.drift.threshold = 0.25;
    c.drift.rearm_threshold = 0.1;
    c.drift.min_samples = 10;
    c.drift.holdoff_arrivals = 1;
    return c;
}

class Feeder {
public:
    explicit Feeder(ArrivalTracker &tracker) : tracker_(tracker) {}
    Outcome send(const std::string &task, const std::string &problem_id = "p",
                 const std::string &problem_text = "") {
        return tracker_.receive({problem_id, "s", task, ++sequence_, NOW_UTIME, problem_text, ""},
                                0, NOW_UTIME);
    }

private:
    ArrivalTracker &tracker_;
    int64_t sequence_ = 0;
};

TEST(Tracker, EstimatesPerProblem) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 0.5}, {"b", 0.5}});
    Feeder feed(tracker);
    for (const char *t : {"a", "a", "a", "b"})
        EXPECT_EQ(feed.send(t).use, Use::ESTIMATED);
    auto s = tracker.status("p");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->estimate, (Distribution{{"a", 0.75}, {"b", 0.25}}));
    EXPECT_DOUBLE_EQ(s->distance, 0.25);
    EXPECT_EQ(s->estimated, 4);
    EXPECT_FALSE(tracker.status("q"));
}

// An initial request never answered is asked again on the clock (answer_timeout_s 120),
// with no arrival; once a design is answered, the clock alone asks for nothing.
TEST(Tracker, AnUnansweredInitialRequestIsAskedAgainOnTheClock) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 0.5}, {"b", 0.5}});
    tracker.initial_request("p", 0);
    EXPECT_TRUE(tracker.requests_due(119).empty());
    auto due = tracker.requests_due(120);
    ASSERT_EQ(due.size(), 1u);
    EXPECT_EQ(due[0].reason, Reason::INITIAL);
    EXPECT_EQ(due[0].estimate, (Distribution{{"a", 0.5}, {"b", 0.5}}));
    EXPECT_EQ(tracker.status("p")->timeouts, 1);
    EXPECT_TRUE(tracker.requests_due(200).empty()); // pending again
    tracker.answered("p", {{"a", 0.5}, {"b", 0.5}}, 210);
    EXPECT_TRUE(tracker.requests_due(1000).empty());
}

TEST(Tracker, UnknownProblemAndUnknownTask) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 1}});
    Feeder feed(tracker);
    EXPECT_EQ(feed.send("a", "nope").verdict, Verdict::UNKNOWN_PROBLEM);
    Outcome o = feed.send("zzz");
    EXPECT_EQ(o.verdict, Verdict::ACCEPTED);
    EXPECT_EQ(o.use, Use::UNKNOWN_TASK);
    feed.send("zzz");
    feed.send("a");
    auto s = tracker.status("p");
    EXPECT_EQ(s->unknown_task, 2);
    EXPECT_EQ(s->unknown_task_names.at("zzz"), 2);
    EXPECT_EQ(s->estimate, (Distribution{{"a", 1}})); // unknown tasks are not estimated
    EXPECT_EQ(tracker.counters().count(Verdict::UNKNOWN_PROBLEM), 1);
}

// Window 10, reference 0.9/0.1, threshold 0.25. After 9 a and 1 b the estimate is the
// reference. Then b's arrive: after k of them the window holds 9-k a's (the oldest leave
// first), TV = k/10: requests at k = 3 (TV 0.3), and, each answer moving the reference to
// the estimate, at k = 6 and k = 9. Without answers: one request only (it stays pending).
TEST(Tracker, ScriptedDriftRequestsAtHandComputedPoints) {
    for (bool answer : {true, false}) {
        ArrivalTracker tracker(tracker_config());
        tracker.add_problem("p", {{"a", 0.9}, {"b", 0.1}});
        Feeder feed(tracker);
        for (int i = 0; i < 9; ++i)
            EXPECT_FALSE(feed.send("a").request);
        EXPECT_FALSE(feed.send("b").request);
        std::vector<int> requested_at;
        for (int k = 1; k <= 9; ++k) {
            Outcome o = feed.send("b");
            if (!o.request)
                continue;
            requested_at.push_back(k);
            EXPECT_EQ(o.request->reason, Reason::DRIFT);
            EXPECT_NEAR(o.request->estimate["a"], (9 - k) / 10.0, 1e-12);
            EXPECT_NEAR(o.request->distance, 0.3, 1e-12);
            if (answer)
                tracker.answered("p", o.request->estimate, 0);
        }
        EXPECT_EQ(requested_at, answer ? (std::vector<int>{3, 6, 9}) : (std::vector<int>{3}));
    }
}

// A new task with its problem: taken in, estimated, and a request that adds it goes out at
// once. The answer includes it: a task of the problem from then on.
TEST(Tracker, NewTaskIsProposedAndAdopted) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 1}});
    Feeder feed(tracker);
    feed.send("a");
    Outcome o = feed.send("c", "p", "(define (problem c) ...)");
    EXPECT_EQ(o.use, Use::NEW_TASK);
    ASSERT_TRUE(o.request);
    EXPECT_EQ(o.request->reason, Reason::NEW_TASK);
    ASSERT_EQ(o.request->new_tasks.size(), 1u);
    EXPECT_EQ(o.request->new_tasks[0].name, "c");
    EXPECT_EQ(o.request->new_tasks[0].problem, "(define (problem c) ...)");
    EXPECT_EQ(o.request->estimate, (Distribution{{"a", 0.5}, {"c", 0.5}}));
    EXPECT_EQ(feed.send("c").use, Use::ESTIMATED); // while pending: provisionally known
    EXPECT_FALSE(tracker.answered("p", {{"a", 0.5}, {"c", 0.5}}, 0));
    EXPECT_EQ(feed.send("c").use, Use::ESTIMATED);
    EXPECT_EQ(tracker.status("p")->new_tasks, 1);
    EXPECT_EQ(tracker.status("p")->refused_tasks, 0);
}

// The answer comes back without the new task: refused, unknown from then on.
TEST(Tracker, RefusedNewTaskBecomesUnknown) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 1}});
    Feeder feed(tracker);
    ASSERT_TRUE(feed.send("c", "p", "(bad pddl").request);
    EXPECT_FALSE(tracker.answered("p", {{"a", 1}}, 0));
    EXPECT_EQ(feed.send("c", "p", "(bad pddl").use, Use::UNKNOWN_TASK);
    EXPECT_EQ(tracker.status("p")->refused_tasks, 1);
}

// A new task arriving while a drift request is pending waits for that answer, then goes out.
TEST(Tracker, NewTaskWhilePendingGoesOutAfterTheAnswer) {
    ArrivalTracker tracker(tracker_config());
    tracker.add_problem("p", {{"a", 0.5}, {"b", 0.5}});
    Feeder feed(tracker);
    std::optional<Request> pending;
    for (int i = 0; i < 10 && !pending; ++i)
        pending = feed.send("a").request;
    ASSERT_TRUE(pending);
    Outcome o = feed.send("c", "p", "(define ...)");
    EXPECT_EQ(o.use, Use::NEW_TASK);
    EXPECT_FALSE(o.request);
    auto next = tracker.answered("p", pending->estimate, 1);
    ASSERT_TRUE(next);
    EXPECT_EQ(next->reason, Reason::NEW_TASK);
    ASSERT_EQ(next->new_tasks.size(), 1u);
    EXPECT_EQ(next->new_tasks[0].name, "c");
}

// Issue 21: 2000 made-up new tasks took the bridge to 50 s of full CPU and a design over
// tasks that do not exist. New tasks are taken in at most `burst` at once, then one per
// interval, and max_new_tasks in all; the rest count as unknown and may come again.
TEST(Tracker, NewTasksAreTakenInAtABoundedRateAndCount) {
    TrackerConfig c = tracker_config();
    c.new_task_burst = 3;
    c.new_task_interval_s = 10;
    c.max_new_tasks = 5;
    ArrivalTracker tracker(c);
    tracker.add_problem("p", {{"a", 1}});
    int64_t sequence = 0;
    auto send = [&](const std::string &task, double now) {
        return tracker.receive({"p", "s", task, ++sequence, NOW_UTIME, "(define ...)", ""}, now,
                               NOW_UTIME);
    };
    int taken = 0;
    for (int i = 0; i < 2000; ++i)
        taken += send("made-up-" + std::to_string(i), 0).use == Use::NEW_TASK;
    EXPECT_EQ(taken, 3);
    EXPECT_EQ(tracker.status("p")->new_tasks_held_back, 1997);
    EXPECT_EQ(send("late", 5).use, Use::UNKNOWN_TASK) << "half an interval later";
    EXPECT_EQ(send("later", 10).use, Use::NEW_TASK) << "one token back";
    EXPECT_EQ(send("much-later", 1000).use, Use::NEW_TASK);
    EXPECT_EQ(send("beyond-the-count", 2000).use, Use::UNKNOWN_TASK) << "5 in all";
    EXPECT_EQ(tracker.status("p")->new_tasks, 5);
}

} // namespace
} // namespace envdesign::arrivals
