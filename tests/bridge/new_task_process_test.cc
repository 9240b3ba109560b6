// New tasks on the wire: an arrival names a task the design problem lacks and brings its PDDL
// problem; the bridge asks for a re-evaluation that adds it, and from the answer on the task
// is the problem's. A new task whose PDDL is broken is refused and counted as unknown; a
// task that comes without its problem is only counted.

#include "harness.h"

#include <set>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

std::string restaurant(const std::string &file) { return SOURCE + "/examples/restaurant/" + file; }

void run_new_task(const std::string &dir, Listener &lcm, Process &bridge, int domain) {
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() == 1; }, 30s)) << bridge.output();
    std::ofstream(dir + "/broken.pddl") << "(define (problem broken) (:domain restaurant)";
    std::vector<std::string> rows;
    for (const auto &task : booth_mix(60, 9))
        rows.push_back(task + ",,");
    rows.push_back("serve-g2-copy," + restaurant("serve-g2.pddl") + "," +
                   restaurant("serve-g2-human.pddl"));
    rows.push_back("broken,broken.pddl,");
    rows.push_back("mop-floor,,");
    publish(dir, write_replay(dir + "/new.csv", "task,problem_file,human_problem_file", rows),
            domain);
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() >= 2; }, 60s)) << bridge.output();
    // Arrivals after the answer: the new task is known, the broken one and mop-floor are not.
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->state == envdesign::task_distribution_t::STATE_ARMED &&
                   lcm.results().size() == lcm.requests().size();
        },
        60s));
    publish(dir,
            write_replay(dir + "/after.csv", "task",
                         {"serve-g2-copy", "serve-g2-copy", "broken", "mop-floor"}),
            domain, {}, "dock-2");
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->received == 67;
        },
        20s));

    // serve-g2-copy goes out at once; broken, arriving while that request is pending, in the
    // next one (or with it, if it came first): either way each once, as a NEW_TASK request.
    std::set<std::string> proposed;
    for (const auto &r : lcm.requests()) {
        if (r.message.reason != envdesign::task_distribution_t::REASON_NEW_TASK)
            continue;
        for (int i = 0; i < r.message.num_new_tasks; ++i) {
            EXPECT_TRUE(proposed.insert(r.message.new_tasks[i]).second) << r.message.new_tasks[i];
            EXPECT_NE(r.message.new_task_problems[i].find("(define"), std::string::npos);
        }
    }
    EXPECT_EQ(proposed, (std::set<std::string>{"broken", "serve-g2-copy"}));

    auto result = lcm.results().back().message;
    EXPECT_EQ(result.exit_code, 0) << result.error;
    std::vector<std::string> tasks;
    for (const auto &t : result.tasks)
        tasks.push_back(t.name);
    EXPECT_EQ(tasks, (std::vector<std::string>{"serve-g1", "serve-g2", "serve-g2-copy"}));

    auto m = *lcm.last_estimate("restaurant");
    EXPECT_GT(probability(m, "serve-g2-copy"), 0);
    EXPECT_EQ(m.unknown_task, 3); // mop-floor twice, broken once after it was refused
    EXPECT_EQ(m.estimated, 64);   // 60 + serve-g2-copy 3 + broken while it was proposed
    std::string log = bridge.output();
    EXPECT_NE(log.find("new task 'serve-g2-copy'"), std::string::npos) << log;
}

TEST(NewTask, AddedAndEvaluatedLocally) {
    std::string dir = scratch("new-local");
    Listener lcm(lcm_url(7766));
    auto bridge = start_bridge(dir, 66, 7766);
    run_new_task(dir, lcm, *bridge, 66);
    EXPECT_NE(bridge->output().find("refused"), std::string::npos);
    // Issue 21: without DDS Security, anyone on the domain publishes; the bridge says so.
    EXPECT_NE(bridge->output().find("DDS Security is off"), std::string::npos) << bridge->output();
    EXPECT_EQ(bridge->stop(), 0);
}

TEST(NewTask, AddedAndEvaluatedByTheCoordinator) {
    std::string dir = scratch("new-coordinator");
    Listener lcm(lcm_url(7767));
    Process coordinator(
        {BIN + "/envdesign-coordinator", "--lcm-url", lcm_url(7767), "--name", "coordinator"}, {},
        dir + "/coordinator.log");
    Process planner({BIN + "/envdesign-planner", "--lcm-url", lcm_url(7767), "--name", "planner-0",
                     "--heartbeat", "0.1"},
                    {}, dir + "/planner.log");
    auto bridge = start_bridge(dir, 67, 7767, {"--redesign", "coordinator"});
    run_new_task(dir, lcm, *bridge, 67);
    EXPECT_EQ(bridge->stop(), 0);
}

} // namespace
} // namespace envdesign::testing
