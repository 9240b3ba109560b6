// Not a test: how fast envdesign-bridge is (issue 6), with real processes over loopback.
//
//   build/tests/bridge_benchmark [throughput|latency|all] [--redesign local|coordinator]
//
// throughput: arrivals from one site at fixed rates for 2 s each, and flat out; what the
//   bridge took per second, and what was lost (sequence gaps).
// latency: the scripted drift back and forth (9:1 <-> 1:9 over two tasks, window 100,
//   threshold 0.3); for every re-evaluation, the time from writing the arrival that crossed
//   the threshold to ENVDESIGN_RESULT arriving here, split at ENVDESIGN_REEVALUATE (DDS in,
//   the bridge's checks and estimate, LCM out) and the re-evaluation itself, with the
//   planner runs it needed (the first flip plans what 9:1 never evaluated; the flips after
//   it are re-weightings of stored evaluations). A pure transport baseline comes first: the
//   same arrival path with no re-evaluation.

#include "harness.h"

#include "arrival_publisher.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace envdesign::testing {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

std::string mode_flag = "local";

struct Cluster {
    std::unique_ptr<Process> coordinator, planner, bridge;
};

Cluster start(const std::string &dir, int domain, int port, std::vector<std::string> flags) {
    Cluster c;
    if (mode_flag == "coordinator") {
        c.coordinator = std::make_unique<Process>(
            std::vector<std::string>{BIN + "/envdesign-coordinator", "--lcm-url", lcm_url(port),
                                     "--name", "coordinator"},
            std::vector<std::string>{}, dir + "/coordinator.log");
        c.planner = std::make_unique<Process>(
            std::vector<std::string>{BIN + "/envdesign-planner", "--lcm-url", lcm_url(port),
                                     "--name", "planner-0", "--heartbeat", "0.1"},
            std::vector<std::string>{}, dir + "/planner.log");
        flags.insert(flags.end(), {"--redesign", "coordinator"});
    }
    c.bridge = start_bridge(dir, domain, port, flags);
    return c;
}

long long seen(Listener &lcm) {
    auto m = lcm.last_estimate("restaurant");
    return m ? m->received + m->sequence_gaps + m->sequence_unseen : 0;
}

void throughput() {
    std::string dir = scratch("bench-throughput");
    Listener lcm(lcm_url(7781));
    auto cluster = start(dir, 81, 7781, {"--threshold", "1", "--publish-hz", "20"});
    arrivals_client::ArrivalPublisher pub({81, "restaurant", "bench", dds::WRITER_HISTORY});
    if (!pub.wait_for_bridge(20)) {
        std::printf("no bridge\n");
        return;
    }
    std::printf("%-12s %12s %12s %10s %10s\n", "offered/s", "published/s", "bridge/s", "lost",
                "drain ms");
    long long total = 0;
    for (double rate : {1000.0, 10000.0, 30000.0, 60000.0, 0.0}) {
        long long n = rate > 0 ? static_cast<long long>(rate * 2) : 200000;
        auto before = lcm.last_estimate("restaurant");
        long long received0 = before ? before->received : 0;
        long long lost0 = before ? before->sequence_gaps + before->sequence_unseen : 0;
        auto t0 = Clock::now();
        for (long long i = 0; i < n; ++i) {
            if (rate > 0)
                std::this_thread::sleep_until(t0 + std::chrono::duration_cast<Clock::duration>(
                                                       std::chrono::duration<double>(i / rate)));
            pub.publish(i % 10 ? "serve-g1" : "serve-g2");
        }
        auto t1 = Clock::now();
        total += n;
        lcm.wait_until([&] { return seen(lcm) >= total; }, 30s);
        auto t2 = Clock::now();
        auto m = *lcm.last_estimate("restaurant");
        long long got = m.received - received0;
        long long lost = m.sequence_gaps + m.sequence_unseen - lost0;
        // The bridge's rate: what it took, over the time from the first write to the last
        // take (as seen here, within one estimate period of 50 ms).
        std::printf("%-12s %12.0f %12.0f %10lld %10.1f\n",
                    rate > 0 ? std::to_string(static_cast<long long>(rate)).c_str() : "flat out",
                    n / std::chrono::duration<double>(t1 - t0).count(),
                    got / std::chrono::duration<double>(t2 - t0).count(), lost, ms(t2 - t1));
    }
    cluster.bridge->stop();
}

struct Crossing {
    int index;         // arrival that crossed
    double to_request; // ms, write -> ENVDESIGN_REEVALUATE heard
    double to_result;  // ms, write -> ENVDESIGN_RESULT heard
    long long planner_runs;
    std::vector<std::string> design;
};

void latency() {
    std::string dir = scratch("bench-latency");
    Listener lcm(lcm_url(7782));
    auto cluster = start(dir, 82, 7782,
                         {"--estimator", "window:100", "--threshold", "0.3", "--rearm", "0.1",
                          "--min-samples", "50", "--holdoff", "1", "--publish-hz", "100000"});
    arrivals_client::ArrivalPublisher pub({82, "restaurant", "bench", dds::WRITER_HISTORY});
    if (!pub.wait_for_bridge(20) ||
        !lcm.wait_until([&] { return lcm.results().size() == 1; }, 30s)) {
        std::printf("no bridge or no first design\n");
        return;
    }
    // One arrival at a time, each after the previous one's estimate was heard, so that the
    // crossing arrival is known and nothing queues behind it.
    std::vector<Clock::time_point> written;
    std::vector<double> transport;
    auto send = [&](const std::string &task) {
        std::size_t requests = lcm.requests().size();
        written.push_back(Clock::now());
        pub.publish(task);
        long long n = static_cast<long long>(written.size());
        lcm.wait_until(
            [&] {
                auto m = lcm.last_estimate("restaurant");
                return m && m->received >= n;
            },
            10s);
        if (lcm.requests().size() > requests) // wait for the answer before going on
            lcm.wait_until([&] { return lcm.results().size() == lcm.requests().size(); }, 60s);
        else
            transport.push_back(ms(lcm.distributions().back().at - written.back()));
    };
    for (int phase = 0; phase < 6; ++phase)
        for (int i = 0; i < 100; ++i)
            send((i % 10 < (phase % 2 ? 1 : 9)) ? "serve-g1" : "serve-g2");

    auto requests = lcm.requests();
    auto results = lcm.results();
    std::vector<Crossing> crossings;
    for (std::size_t i = 1; i < requests.size() && i < results.size(); ++i) {
        int index = static_cast<int>(requests[i].message.estimated) - 1;
        crossings.push_back({index, ms(requests[i].at - written[index]),
                             ms(results[i].at - written[index]),
                             results[i].message.counters.planner_runs, results[i].message.design});
    }
    std::sort(transport.begin(), transport.end());
    std::printf("transport (arrival written -> its estimate heard, no re-evaluation): median "
                "%.3f ms, p90 %.3f ms over %zu arrivals\n",
                transport[transport.size() / 2], transport[transport.size() * 9 / 10],
                transport.size());
    std::printf("%-8s %14s %14s %16s %14s  %s\n", "arrival", "to request ms", "to result ms",
                "re-evaluation ms", "planner runs", "design");
    for (const auto &c : crossings) {
        std::string design;
        for (const auto &d : c.design)
            design += d + " ";
        std::printf("%-8d %14.3f %14.3f %16.3f %14lld  {%s}\n", c.index, c.to_request, c.to_result,
                    c.to_result - c.to_request, c.planner_runs, design.c_str());
    }
    cluster.bridge->stop();
}

} // namespace
} // namespace envdesign::testing

int main(int argc, char **argv) {
    std::string part = argc > 1 ? argv[1] : "all";
    for (int i = 2; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--redesign")
            envdesign::testing::mode_flag = argv[i + 1];
    setenv("CYCLONEDDS_URI",
           ("file://" + envdesign::testing::SOURCE + "/deploy/cyclonedds-loopback.xml").c_str(), 1);
    std::printf("envdesign-bridge, --redesign %s\n", envdesign::testing::mode_flag.c_str());
    if (part == "throughput" || part == "all")
        envdesign::testing::throughput();
    if (part == "latency" || part == "all")
        envdesign::testing::latency();
}
