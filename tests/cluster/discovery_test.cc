// A coordinator that is still discovering (cluster/election.h) says nothing to clients:
// another coordinator on the bus may be answering the same request. Its refusals wait until
// it knows it is active (one per request, however often the client re-sends), and go when
// it hears an earlier coordinator and stands by.

#include "harness.h"

#include "bus/log.h"
#include "envdesign/service_status_t.hpp"

#include <atomic>
#include <memory>

namespace envdesign::cluster::testing {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// Results and progress messages published for request `id`, and the standby statuses,
// counted on the bus thread.
struct Heard {
    std::atomic<int> results{0};
    std::atomic<int> progress{0};
    std::atomic<int> standby{0};
};

// MemqCluster's setup: the subscriptions live in the tick it returns, which the cluster
// drops after its loop stops and before its bus goes.
std::function<std::function<void()>(bus::Bus &)> count_into(Heard &heard, std::int64_t id) {
    return [&heard, id](bus::Bus &bus) {
        auto subscriptions = std::make_shared<std::vector<bus::Subscription>>();
        subscriptions->push_back(bus.subscribe<envdesign::design_result_t>(
            bus::RESULT, [&heard, id](const envdesign::design_result_t &r) {
                heard.results += r.request_id == id ? 1 : 0;
            }));
        subscriptions->push_back(bus.subscribe<envdesign::design_progress_t>(
            bus::PROGRESS, [&heard, id](const envdesign::design_progress_t &p) {
                heard.progress += p.request_id == id ? 1 : 0;
            }));
        subscriptions->push_back(bus.subscribe<envdesign::service_status_t>(
            bus::STATUS, [&heard](const envdesign::service_status_t &s) {
                heard.standby += s.role == "standby" ? 1 : 0;
            }));
        return std::function<void()>([subscriptions] {});
    };
}

void discover_for(CoordinatorConfig &c, double seconds) { c.election.discovery_s = seconds; }

TEST(Discovery, RefusalsWaitForTheEndOfDiscoveryOncePerRequest) {
    Heard heard;
    auto start = Clock::now();
    MemqCluster cluster(1, 1, count_into(heard, 5),
                        [](CoordinatorConfig &c) { discover_for(c, 0.6); });
    auto request = request_of(in_repo("examples/restaurant/a-one-task-t1.textproto"), 5);
    request.heuristic = 9;        // bad input: refused at once by an active coordinator
    for (int i = 0; i < 3; ++i) { // the client re-sends while it hears nothing
        cluster.bus().publish(bus::REQUEST, request);
        std::this_thread::sleep_for(100ms);
    }
    EXPECT_EQ(heard.results, 0) << "answered while discovering";
    auto result = cluster.wait(5, 5);
    EXPECT_GE(std::chrono::duration<double>(Clock::now() - start).count(), 0.6);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.error, "bad request: unknown heuristic 9");
    std::this_thread::sleep_for(200ms);
    EXPECT_EQ(heard.results, 1);
}

TEST(Discovery, AValidRequestIsTakenSilentlyAndAnsweredOnceActive) {
    Heard heard;
    MemqCluster cluster(1, 1, count_into(heard, 6),
                        [](CoordinatorConfig &c) { discover_for(c, 0.6); });
    auto request = request_of(in_repo("examples/restaurant/a-one-task-t1.textproto"), 6);
    cluster.bus().publish(bus::REQUEST, request);
    std::this_thread::sleep_for(100ms);
    cluster.bus().publish(bus::REQUEST, request); // a repeat: no "still at it" yet
    std::this_thread::sleep_for(200ms);
    EXPECT_EQ(heard.progress, 0);
    EXPECT_EQ(heard.results, 0);
    auto result = cluster.wait(6, 30);
    EXPECT_EQ(result.exit_code, 0) << result.error;
    EXPECT_GT(heard.progress, 0);
    std::this_thread::sleep_for(200ms);
    EXPECT_EQ(heard.results, 1);
}

TEST(Discovery, HeardAnEarlierCoordinatorItNeverAnswers) {
    Heard heard;
    MemqCluster cluster(1, 1, count_into(heard, 7),
                        [](CoordinatorConfig &c) { discover_for(c, 0.6); });
    auto request = request_of(in_repo("examples/restaurant/a-one-task-t1.textproto"), 7);
    request.heuristic = 9;
    cluster.bus().publish(bus::REQUEST, request);
    envdesign::service_status_t other{};
    other.kind = "coordinator";
    other.sender = "coordinator"; // its own name: two clusters started alike
    other.started_utime = bus::now_utime() - 60'000'000;
    other.role = "active";
    // Its statuses past the discovery, until this one's own status (once a second) says it
    // stands by.
    for (int i = 0; i < 30 && (i < 10 || heard.standby == 0); ++i) {
        other.utime = bus::now_utime();
        cluster.bus().publish(bus::STATUS, other);
        std::this_thread::sleep_for(100ms);
    }
    EXPECT_GT(heard.standby, 0);
    EXPECT_EQ(heard.results, 0);
    EXPECT_EQ(heard.progress, 0);
}

} // namespace
} // namespace envdesign::cluster::testing
