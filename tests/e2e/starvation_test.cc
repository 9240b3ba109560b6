// Work is bounded per request (issue 21, real processes): a job that never ends (blind search
// on a state space of 2^30 states) is stopped by its memory limit and by the coordinator's
// cap on time limits, is never run twice at once while its planner works on it, and a
// SIGTERM stops the planner within a second; a request with a 30 KB client name is refused
// and nothing of it kept.

#include "local_cluster.h"
#include "never_ending_spec.h"

#include "bus/codec.h"
#include "bus/log.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "spec/spec_bundle.h"

#include <envdesign/client/client.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <iostream>

namespace envdesign::e2e {
namespace {

namespace fs = std::filesystem;

class Starvation : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("envdesign-starvation-" + std::to_string(getpid()));
        fs::remove_all(dir);
        spec = write_switches_spec(dir);
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir);
    }
    client::Result blind(const LocalCluster &cluster, double time_limit_s) {
        client::Options options;
        options.heuristic = "blind";
        options.time_limit_s = time_limit_s;
        options.give_up_after_s = 60;
        return client::run_design_remote(spec, cluster.url(), options);
    }
    fs::path dir;
    std::string spec;
};

double median(std::vector<double> seconds) {
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
}

// A copy of blocksworld problem 14 (3 tasks, 6 modifications: about 2 s of work on two quiet
// planners) whose PDDL files end in a comment of their own: a planner keeps its plans by
// spec, so a second run of the same spec is nearly free (0.1 s); each timed run asks anew.
std::string fresh_blocksworld(const fs::path &dir, int copy) {
    const fs::path from = source("tests/data/paper/blocksworld");
    const fs::path to = dir / ("blocksworld-" + std::to_string(copy));
    fs::create_directories(to / "14");
    auto copy_file = [&](const fs::path &file, const fs::path &into) {
        std::ifstream in(file);
        std::ofstream out(into / file.filename());
        out << in.rdbuf();
        if (file.extension() == ".pddl")
            out << "\n; copy " << copy << "\n";
    };
    for (const auto &entry : fs::directory_iterator(from))
        if (entry.path().extension() == ".pddl")
            copy_file(entry.path(), to);
    for (const auto &entry : fs::directory_iterator(from / "14"))
        copy_file(entry.path(), to / "14");
    return (to / "14" / "design-t10.textproto").string();
}

// The seconds `spec` took through the cluster, its JSON result in `json`.
double timed_design(const std::string &spec, LocalCluster &cluster, const client::Options &options,
                    nlohmann::json &json) {
    auto start = std::chrono::steady_clock::now();
    client::Result result = client::run_design_remote(spec, cluster.url(), options);
    double took = seconds_since(start);
    EXPECT_EQ(result.exit_code, 0) << spec << ": " << result.error << cluster.logs();
    if (result.exit_code == 0)
        json = nlohmann::json::parse(result.json);
    return took;
}

// A request without a time limit ends at the coordinator's --max-time-limit: exit 4 with
// the best design found, not a search that holds a slot and the planners for ever.
TEST_F(Starvation, ARequestWithoutATimeLimitEndsAtTheCoordinatorsCap) {
    LocalCluster cluster(1, {"--max-time-limit", "3"});
    auto start = std::chrono::steady_clock::now();
    client::Result result = blind(cluster, 0);
    double took = seconds_since(start);
    EXPECT_EQ(result.exit_code, 4) << result.error << cluster.logs();
    EXPECT_LT(took, 15) << cluster.logs();
    EXPECT_GT(took, 2.5);
}

// One job's search stops at --job-memory-mb: the planner's resident memory stays under it
// (it grew to ~900 MB within a minute) and the job is answered as out of limits.
TEST_F(Starvation, APlannerJobStopsAtItsMemoryLimit) {
    LocalCluster cluster(0, {"--max-time-limit", "8"});
    Process &planner = cluster.add_planner({"--job-memory-mb", "64"});
    std::atomic<bool> done{false};
    long most = 0;
    std::thread sampler([&] {
        while (!done) {
            most = std::max(most, resident_kib(planner.pid()));
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    });
    client::Result result = blind(cluster, 0);
    done = true;
    sampler.join();
    EXPECT_EQ(result.exit_code, 4) << result.error;
    EXPECT_TRUE(planner.running()) << cluster.logs();
    std::cout << "planner RSS at most " << most / 1024 << " MiB with --job-memory-mb 64\n";
    // The limit holds for the process: the search gets what its code, specs and caches leave.
    EXPECT_LT(most, 64 * 1024) << "planner reached " << most << " KiB\n" << cluster.logs();
}

// The job deadline (0.5 s here) passes long before a blind search ends; the planner's
// heartbeats show it working, so the job is not handed to the second planner.
TEST_F(Starvation, AJobItsPlannerIsWorkingOnIsNeverSentTwice) {
    LocalCluster cluster(2, {"--job-deadline", "0.5"});
    client::Result result = blind(cluster, 6);
    EXPECT_EQ(result.exit_code, 4) << result.error;
    EXPECT_EQ(cluster.coordinator().output().find("missed its deadline"), std::string::npos)
        << cluster.logs();
}

// SIGTERM in the middle of a search that would run for hours: the planner says it is
// stopping, stops the search and exits within a second (it waited for the search).
TEST_F(Starvation, APlannerStopsWithinASecondOfSigterm) {
    LocalCluster cluster(1);
    std::thread request([&] { blind(cluster, 20); });
    ASSERT_TRUE(wait_for_output(cluster.planner(0), "spec", 10)) << cluster.logs();
    std::this_thread::sleep_for(std::chrono::seconds(2)); // deep in the search
    auto start = std::chrono::steady_clock::now();
    cluster.planner(0).signal(SIGTERM);
    int code = cluster.planner(0).wait();
    double took = seconds_since(start);
    request.join();
    EXPECT_EQ(code, 0) << cluster.logs();
    EXPECT_LT(took, 1.0) << cluster.logs();
    std::cout << "planner exited " << took << " s after SIGTERM\n";
}

// The audit's flood: forty requests that never end (blind search, no time limit), from forty
// client names in one process, against a well-behaved client. Fair shares go by client
// (fair_share.h): the process that sent them, signed on a keyed bus and declared on an
// unkeyed one (the flood is one client). The well-behaved
// client's request must finish within twice its quiet time (keyed: the flood has used the
// planners far more lately, so the request takes every planner it asks for at once); the
// planners' resident memory stays under --job-memory-mb. Two sizes, three runs each (the
// medians are compared), quiet then flooded: the restaurant (0.04 s quiet, where withdrawing
// the flood's searches is most of the time) and blocksworld 14 (a few seconds of planner
// work: the share of the planners is what counts). ENVDESIGN_FLOOD_LOGS=FILE writes the
// services' logs there, at debug level (each job sent and answered, with times).
void flood_against_a_client(const fs::path &dir, const std::string &spec, bool keyed) {
    std::string key;
    if (keyed) {
        key = (dir / "bus.key").string();
        std::ofstream(key) << "k1 " << std::string(64, '7') << "\n";
        fs::permissions(key, fs::perms::owner_read | fs::perms::owner_write);
    }
    // Nothing remembered: every run of the restaurant plans (else the second is free).
    const char *logs = std::getenv("ENVDESIGN_FLOOD_LOGS");
    const std::string level = logs ? "debug" : "info";
    LocalCluster cluster(0, {"--stored-evaluations", "0", "--log-level", level}, key);
    std::vector<Process *> planners;
    for (int i = 0; i < 2; ++i)
        planners.push_back(&cluster.add_planner(
            {"--job-memory-mb", "128", "--remembered-answers", "0", "--log-level", level}));
    const std::string restaurant = source("examples/restaurant/c-two-tasks-t10.textproto");
    client::Options options;
    options.give_up_after_s = 60;
    options.timeout_s = 30; // a starved request fails after 30 s, not when the flood ends
    options.key_file = key;
    nlohmann::json small, large, want_large;
    timed_design(restaurant, cluster, options, small); // warm: the coordinator is past discovery
    constexpr int RUNS = 3;
    std::vector<double> quiet_small, quiet_large, flooded_small, flooded_large;
    for (int run = 0; run < RUNS; ++run) {
        quiet_small.push_back(timed_design(restaurant, cluster, options, small));
        quiet_large.push_back(
            timed_design(fresh_blocksworld(dir, run), cluster, options, want_large));
    }

    bus::Bus flood(
        cluster.url(),
        std::make_shared<spdlog::logger>("flood", std::make_shared<spdlog::sinks::null_sink_mt>()),
        keyed ? std::make_shared<const bus::KeyRing>(bus::load_key_file(key)) : nullptr);
    envdesign::spec_t never_ending = spec::bundle_spec(spec);
    for (int i = 0; i < 40; ++i) {
        envdesign::design_request_t request{};
        request.utime = bus::now_utime();
        request.request_id = 1;
        request.sender = "flood-" + std::to_string(i);
        request.spec = never_ending;
        request.time_limit_s = 0;
        request.max_design_size = -1;
        request.heuristic = envdesign::design_request_t::HEURISTIC_BLIND;
        flood.publish(bus::REQUEST, request);
    }
    std::atomic<bool> done{false};
    long most = 0;
    std::thread sampler([&] {
        for (int tick = 0; !done; ++tick) {
            for (Process *p : planners)
                most = std::max(most, resident_kib(p->pid()));
            if (tick % 20 == 0) // a live client: it says it still waits (else it is dropped)
                for (int i = 0; i < 40; ++i) {
                    envdesign::keepalive_t keepalive{};
                    keepalive.utime = bus::now_utime();
                    keepalive.request_id = 1;
                    keepalive.sender = "flood-" + std::to_string(i);
                    flood.publish(bus::KEEPALIVE, keepalive);
                }
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    });
    std::this_thread::sleep_for(std::chrono::seconds(5)); // the flood holds every planner
    for (int run = 0; run < RUNS; ++run) {
        // A request that failed (timed_design said so) leaves its JSON empty: nothing to compare
        // (at() would throw past the sampler thread, and end the whole test program).
        small = large = nlohmann::json();
        flooded_small.push_back(timed_design(restaurant, cluster, options, small));
        if (!small.is_null())
            expect_same_design(small, self_contained(restaurant));
        flooded_large.push_back(
            timed_design(fresh_blocksworld(dir, RUNS + run), cluster, options, large));
        if (!large.is_null() && !want_large.is_null())
            expect_same_design(large, want_large);
        std::this_thread::sleep_for(std::chrono::seconds(1)); // the flood takes the planners back
    }
    done = true;
    sampler.join();
    auto print = [](const char *name, const std::vector<double> &quiet,
                    const std::vector<double> &flooded) {
        std::cout << name << ": quiet";
        for (double s : quiet)
            std::cout << " " << s;
        std::cout << " s (median " << median(quiet) << "), under the flood";
        for (double s : flooded)
            std::cout << " " << s;
        std::cout << " s (median " << median(flooded) << "): " << median(flooded) / median(quiet)
                  << "x\n";
    };
    print("restaurant", quiet_small, flooded_small);
    print("blocksworld 14", quiet_large, flooded_large);
    std::cout << "planner RSS at most " << most / 1024 << " MiB\n";
    if (logs)
        std::ofstream(logs) << cluster.logs();
    // Within 2x only on a quiet machine: withdrawing the flood's searches takes their planners
    // tens of milliseconds, and on a loaded one their bus threads hear of it late
    // (docs/results/robustness.md); 0.5 s allows for that, for both sizes (blocksworld once
    // failed at 2.001x in CI). A starved request takes 10-80 s, or the 30 s timeout.
    EXPECT_LT(median(flooded_small), 2 * median(quiet_small) + 0.5) << cluster.logs();
    EXPECT_LT(median(flooded_large), 2 * median(quiet_large) + 0.5) << cluster.logs();
    EXPECT_LT(most, 128 * 1024) << "KiB: the planner's resident memory passed --job-memory-mb";
}

TEST_F(Starvation, AFloodOfNeverEndingRequestsDoesNotStarveAnotherClient) {
    flood_against_a_client(dir, spec, true);
}

// The same flood on an unkeyed bus. By name the flood would be 40 of 41 equal clients (the
// well-behaved one had 2/41 of the planners at best: restaurant 9.8-80 s under the flood,
// quiet 0.02-0.05 s; blocksworld 14 at the 30 s timeout, quiet 1.6-2.5 s). The unit is now
// the process the messages declare (bus/auth.h's origin trailer, cluster/coordinator.h's
// client_unit), so the forty names are one client here too: at most max_per_client of
// them are taken, and they share one part of the planners.
TEST_F(Starvation, AFloodFromFortyNamesOnAnUnkeyedBusDoesNotStarveAnotherClient) {
    flood_against_a_client(dir, spec, false);
}

// A refused request is not kept: 30 KB client names took the coordinator from 297 to 769 MB.
TEST(Requests, AHugeClientNameIsRefusedAndNothingOfItIsKept) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "client", std::make_shared<spdlog::sinks::null_sink_mt>()));
    int results = 0;
    auto sub = bus.subscribe<envdesign::design_result_t>(
        bus::RESULT, [&](const envdesign::design_result_t &) { ++results; });
    long before = resident_kib(cluster.coordinator().pid());
    for (int i = 0; i < 300; ++i) {
        envdesign::design_request_t request{};
        request.request_id = i + 1;
        request.sender = std::string(30'000, 'n') + std::to_string(i);
        request.time_limit_s = -1;
        request.max_design_size = -1;
        bus.publish(bus::REQUEST, request);
        bus.handle(std::chrono::milliseconds(1));
    }
    bus.handle(std::chrono::milliseconds(1000));
    long after = resident_kib(cluster.coordinator().pid());
    EXPECT_EQ(results, 0);
    EXPECT_LT(after - before, 20 * 1024) << before << " -> " << after << " KiB";
    std::cout << "coordinator " << before / 1024 << " -> " << after / 1024
              << " MiB after 300 requests with 30 KB names\n";
    EXPECT_NE(cluster.coordinator().output().find("a client name of 30001 bytes"),
              std::string::npos)
        << cluster.logs();
    client::Options options;
    options.give_up_after_s = 20;
    EXPECT_EQ(client::run_design_remote(source("examples/restaurant/c-two-tasks-t10.textproto"),
                                        cluster.url(), options)
                  .exit_code,
              0)
        << cluster.logs();
}

} // namespace
} // namespace envdesign::e2e
