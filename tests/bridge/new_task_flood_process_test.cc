// A flood of made-up new tasks on DDS against a real bridge (issue 21): without DDS Security
// anyone on the domain may publish arrivals that carry a task's problem, and 2000 of them
// gave the bridge 50 s of full CPU and a design over tasks that do not exist. The bridge
// takes in at most --max-new-tasks (and --new-task-burst at once, then one per
// --new-task-interval); the rest are held back and counted, it still re-designs over the real
// tasks, and it says at start that DDS Security is off.

#include "harness.h"

#include <iostream>
#include <set>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

constexpr int FLOOD = 2000;
constexpr int MAX_NEW_TASKS = 8;
// The bridge's CPU over the flood and the re-designs after it, seconds. Bounded, it takes
// about 1 s; taking in every made-up task took 50 s (issue 21's audit).
constexpr double CPU_BOUND_S = 10;

// Every new task the bridge asked a re-evaluation to add, by name.
std::set<std::string> proposed_tasks(Listener &lcm) {
    std::set<std::string> names;
    for (const auto &r : lcm.requests())
        for (int i = 0; i < r.message.num_new_tasks; ++i)
            names.insert(r.message.new_tasks[i]);
    return names;
}

// Every request the bridge sent has its answer, and the detector is armed again.
bool settled(Listener &lcm) {
    auto m = lcm.last_estimate("restaurant");
    return m && m->state == envdesign::task_distribution_t::STATE_ARMED &&
           lcm.results().size() == lcm.requests().size();
}

TEST(NewTaskFlood, MadeUpNewTasksAreHeldBackCountedAndCheap) {
    std::string dir = scratch("new-task-flood");
    Listener lcm(lcm_url(7784));
    auto bridge =
        start_bridge(dir, 84, 7784,
                     {"--max-new-tasks", std::to_string(MAX_NEW_TASKS), "--new-task-burst",
                      std::to_string(MAX_NEW_TASKS), "--new-task-interval", "1"});
    ASSERT_TRUE(lcm.wait_until([&] { return lcm.results().size() == 1; }, 30s)) << bridge->output();
    EXPECT_NE(bridge->output().find("DDS Security is off"), std::string::npos) << bridge->output();
    // The site's real traffic first: the spec's own 9:1 mix.
    publish(dir, write_replay(dir + "/real.csv", "task", booth_mix(100, 9)), 84);
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 100 && settled(lcm);
        },
        30s))
        << bridge->output();
    const std::size_t results_before = lcm.results().size();
    const double cpu_before = cpu_seconds(bridge->pid());

    std::string problem = SOURCE + "/examples/restaurant/serve-g2.pddl";
    std::string human = SOURCE + "/examples/restaurant/serve-g2-human.pddl";
    std::vector<std::string> rows;
    for (int i = 0; i < FLOOD; ++i)
        rows.push_back("made-up-" + std::to_string(i) + "," + problem + "," + human);
    publish(dir, write_replay(dir + "/flood.csv", "task,problem_file,human_problem_file", rows), 84,
            {"--ack-timeout", "30", "--history", "4096"}, "rogue");
    // The publisher keeps every arrival for the bridge (--history): none is lost, and were one,
    // it would show in the sequence numbers.
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->received + m->sequence_gaps + m->sequence_unseen == 100 + FLOOD;
        },
        30s))
        << bridge->output();
    ASSERT_TRUE(lcm.wait_until([&] { return settled(lcm); }, 60s)) << bridge->output();
    const auto flooded = *lcm.last_estimate("restaurant");
    const long long arrived = flooded.received - 100;
    const std::set<std::string> admitted = proposed_tasks(lcm);
    EXPECT_LE(admitted.size(), static_cast<std::size_t>(MAX_NEW_TASKS));
    EXPECT_GE(admitted.size(), 1u);
    // Each made-up task arrived once: all but the admitted ones were held back, and counted.
    EXPECT_TRUE(lcm.wait_until(
        [&] {
            return lcm.status_drops("bridge/test", "dds:arrivals", "new_task_held_back") ==
                   arrived - static_cast<long long>(admitted.size());
        },
        5s))
        << "held back: " << lcm.status_drops("bridge/test", "dds:arrivals", "new_task_held_back")
        << ", arrived " << arrived << ", admitted " << admitted.size();
    EXPECT_EQ(flooded.unknown_task, arrived - static_cast<long long>(admitted.size()));

    // The real traffic moves to 1:9: the bridge re-designs over the real tasks.
    publish(dir, write_replay(dir + "/drift.csv", "task", booth_mix(100, 1)), 84);
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("restaurant");
            return m && m->estimated == 200 + static_cast<long long>(admitted.size()) &&
                   settled(lcm) &&
                   lcm.requests().back().message.reason ==
                       envdesign::task_distribution_t::REASON_DRIFT;
        },
        60s))
        << bridge->output();
    const double cpu = cpu_seconds(bridge->pid()) - cpu_before;
    auto results = lcm.results();
    ASSERT_GT(results.size(), results_before + 1);
    auto last = results.back().message;
    EXPECT_EQ(last.exit_code, 0) << last.error;
    std::set<std::string> tasks;
    for (const auto &t : last.tasks)
        tasks.insert(t.name);
    EXPECT_TRUE(tasks.count("serve-g1") && tasks.count("serve-g2"));
    EXPECT_LE(tasks.size(), 2u + MAX_NEW_TASKS);
    std::cout << "flood of " << FLOOD << " made-up new tasks: " << arrived << " arrived, "
              << admitted.size() << " taken in, bridge CPU " << cpu << " s over the flood and "
              << results.size() - results_before << " re-designs\n";
    EXPECT_LT(cpu, CPU_BOUND_S);

    std::string log = bridge->output();
    EXPECT_NE(log.find("held back"), std::string::npos) << log;
    EXPECT_LT(std::count(log.begin(), log.end(), '\n'), 200) << log; // the flood, throttled
    EXPECT_TRUE(bridge->running());
    EXPECT_EQ(bridge->stop(), 0);
}

} // namespace
} // namespace envdesign::testing
