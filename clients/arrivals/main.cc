// envdesign-arrivals: publishes task arrivals on DDS for envdesign-bridge, from a replay file
// (replay.h) or as N arrivals of one task, at a given rate.
//
//   envdesign-arrivals --replay FILE.csv --rate HZ --problem ID [--site S] [--domain N]
//   envdesign-arrivals --task NAME --count N --rate HZ --problem ID
//   envdesign-arrivals --replay TRIPS.csv --floor DIR --problem ID   (columns from, to)
//
// Exit codes (SPEC.md): 0 all published (and acknowledged by the bridges matched), 2 bad
// input or usage, 4 --wait-bridge timed out or acknowledgements did not come, 1 a DDS error.

#include "arrival_publisher.h"
#include "replay.h"

#include "floor/floor_draw.h"
#include "floor/floor_error.h"
#include "floor/floor_names.h"
#include "pddl/parse_error.h"
#include "service/number_flag.h"

#include <CLI/CLI.hpp>
#include <envdesign/version.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

namespace {

using namespace envdesign;

std::atomic<bool> g_stop{false}; // set by SIGINT/SIGTERM only

struct Flags {
    std::string replay, task, problem_id, site = "replay";
    std::string floor; // a folder `envdesign floor import` wrote: names the trips' tasks
    long long count = 1;
    int repeat = 1, domain = 0, history = dds::WRITER_HISTORY;
    double rate = 0, wait_bridge = 0, linger = 1, ack_timeout = 5;
};

// Sleeps until `when` unless a signal comes first; false if it did.
bool pace(std::chrono::steady_clock::time_point when) {
    while (!g_stop && std::chrono::steady_clock::now() < when)
        std::this_thread::sleep_until(
            std::min(when, std::chrono::steady_clock::now() + std::chrono::milliseconds(100)));
    return !g_stop;
}

std::vector<arrivals_client::ReplayRow> rows_of(const Flags &f) {
    if (!f.replay.empty()) {
        std::vector<arrivals_client::ReplayRow> rows = arrivals_client::read_replay_file(f.replay);
        if (f.floor.empty()) {
            arrivals_client::name_trips(rows, nullptr);
            return rows;
        }
        floor::FloorNames names(floor::read_floor_json(f.floor));
        arrivals_client::name_trips(rows,
                                    [&](const std::string &from, const std::string &to,
                                        std::string &why) { return names.task(from, to, why); });
        return rows;
    }
    std::vector<arrivals_client::ReplayRow> rows(static_cast<std::size_t>(f.count));
    for (auto &row : rows)
        row.task = f.task;
    return rows;
}

int publish(const Flags &f, const std::vector<arrivals_client::ReplayRow> &rows) {
    arrivals_client::ArrivalPublisher publisher({f.domain, f.problem_id, f.site, f.history});
    if (f.wait_bridge > 0 && !publisher.wait_for_bridge(f.wait_bridge)) {
        std::cerr << "envdesign-arrivals: no bridge matched within " << f.wait_bridge << " s\n";
        return 4;
    }
    arrivals_client::ReplayNumbering numbering;
    auto start = std::chrono::steady_clock::now();
    long long sent = 0;
    for (int r = 0; r < f.repeat && !g_stop; ++r) {
        for (const auto &row : rows) {
            if (f.rate > 0 && !pace(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                std::chrono::duration<double>(sent / f.rate))))
                break;
            publisher.publish_raw(
                numbering.arrival(row, f.problem_id, f.site, arrivals_client::now_utime()));
            ++sent;
        }
    }
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << "envdesign-arrivals: published " << sent << " arrivals in " << seconds << " s\n";
    bool acknowledged = publisher.flush(f.ack_timeout);
    // Stay: the writer's durable history is what bridges that join late receive.
    pace(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                std::chrono::duration<double>(f.linger)));
    if (!acknowledged)
        std::cerr << "envdesign-arrivals: not every arrival was acknowledged within "
                  << f.ack_timeout << " s\n";
    return acknowledged ? 0 : 4;
}

} // namespace

int main(int argc, char **argv) {
    CLI::App app{"envdesign-arrivals: publish task arrivals on DDS (TaskArrival topic)"};
    Flags f;
    app.set_version_flag("--version", envdesign::version_line("envdesign-arrivals"));
    auto *replay = app.add_option("--replay", f.replay, "CSV replay file (one arrival a line)");
    auto *task = app.add_option("--task", f.task, "publish --count arrivals of this task");
    replay->excludes(task);
    app.add_option("--count", f.count, "arrivals for --task")->check(CLI::NonNegativeNumber);
    app.add_option("--rate", f.rate, "arrivals per second (0: as fast as possible)")
        ->check(service::number_in({0, 1e6}));
    app.add_option("--repeat", f.repeat, "replay the file this many times")
        ->check(CLI::PositiveNumber);
    app.add_option("--problem", f.problem_id, "design problem id (rows may override)");
    app.add_option("--site", f.site, "site name (rows may override)");
    app.add_option("--floor", f.floor,
                   "an imported floor's folder: replay rows may give from,to (vI or a place's "
                   "name) for the task vI-vJ");
    app.add_option("--domain", f.domain, "DDS domain id")->check(CLI::Range(0, 230));
    app.add_option("--history", f.history, "arrivals kept per site for late bridges")
        ->check(CLI::PositiveNumber);
    app.add_option("--wait-bridge", f.wait_bridge, "wait up to S seconds for a bridge first")
        ->check(service::number_in(design::TIME_LIMIT_S));
    // A bridge that matched this writer a moment ago may still be discovering it; until it
    // has, it does not acknowledge, and Cyclone's wait for acknowledgements does not wait for
    // it. Staying a little serves it the history (TRANSIENT_LOCAL) once it has.
    app.add_option("--linger", f.linger, "stay S seconds after the last arrival")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    app.add_option("--ack-timeout", f.ack_timeout, "seconds to wait for acknowledgements")
        ->check(service::number_in(design::TIME_LIMIT_S));
    try {
        app.parse(argc, argv);
        if (f.replay.empty() && f.task.empty())
            throw CLI::RequiredError("--replay or --task");
    } catch (const CLI::ParseError &e) {
        int rc = app.exit(e);
        return rc == 0 ? 0 : 2;
    }
    std::signal(SIGINT, [](int) { g_stop = true; });
    std::signal(SIGTERM, [](int) { g_stop = true; });
    try {
        return publish(f, rows_of(f));
    } catch (const pddl::ParseError &e) {
        std::cerr << e.what() << "\n";
        return 2;
    } catch (const floor::FloorError &e) {
        std::cerr << "envdesign-arrivals: " << e.what() << "\n";
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "envdesign-arrivals: " << e.what() << "\n";
        return 1;
    }
}
