#pragma once
// Real service processes on loopback udpm for the end-to-end tests: a coordinator and
// planners started from build/bin, each test on its own UDP port (PLATFORM.md: ports
// isolate, group addresses do not), logs in a temporary directory.

#include "bus/bus.h"
#include "bus/channels.h"
#include "envdesign/planner_heartbeat_t.hpp"

#include "../support/ports.h"
#include "../support/process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <spdlog/sinks/null_sink.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace envdesign::e2e {

// The specs several files here run (relative to the source tree: source(RESTAURANT)). The
// test files compile in unity batches (tests/CMakeLists.txt): a name two of them need is
// defined here once.
inline const char *const RESTAURANT = "examples/restaurant/c-two-tasks-t10.textproto";
inline const char *const WAREHOUSE = "tests/e2e/data/warehouse/signs-2.textproto";

inline std::string source(const std::string &relative) {
    return std::string(ENVDESIGN_TEST_DATA_ROOT) + "/" + relative;
}
inline std::string binary(const std::string &name) {
    return std::string(ENVDESIGN_BIN_DIR) + "/" + name;
}

// A URL of our own for this test process (a port claimed for it, ../support/ports.h); `n` > 0
// for more clusters at once. The same `n` gives the same URL.
inline std::string unique_url(int n = 0) {
    static std::mutex mutex;
    static std::map<int, int> ports;
    std::lock_guard lock(mutex);
    auto [at, claimed] = ports.try_emplace(n, 0);
    if (claimed)
        at->second = testing::claim_udp_port();
    return testing::udpm_test_url(at->second) + "&recv_buf_size=4194304";
}

using testing::Process;

// Seconds from `start` to now.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// True once `line` is in what `p` printed, false if `timeout_s` passes first.
inline bool wait_for_output(Process &p, const std::string &line, double timeout_s = 10) {
    auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < end) {
        if (p.output().find(line) != std::string::npos)
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

// Resident memory of process `pid` in KiB (/proc/PID/status, VmRSS).
inline long resident_kib(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string key;
    long value = -1;
    while (status >> key) {
        if (key == "VmRSS:") {
            status >> value;
            break;
        }
        status.ignore(1 << 20, '\n');
    }
    return value;
}

// Hears heartbeats, to know which planners the coordinator can see.
class HeartbeatWatcher {
public:
    explicit HeartbeatWatcher(const std::string &url,
                              std::shared_ptr<const bus::KeyRing> keys = nullptr)
        : bus_(url,
               std::make_shared<spdlog::logger>("watcher",
                                                std::make_shared<spdlog::sinks::null_sink_mt>()),
               std::move(keys)) {
        sub_ = bus_.subscribe<envdesign::planner_heartbeat_t>(
            bus::HEARTBEAT, [this](const envdesign::planner_heartbeat_t &b) {
                if (!b.stopping)
                    seen_.insert(b.sender);
            });
    }
    // True once `name` was heard within `timeout_s`.
    bool wait_for(const std::string &name, double timeout_s = 10) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
        while (!seen_.count(name) && std::chrono::steady_clock::now() < end)
            bus_.handle(std::chrono::milliseconds(20));
        return seen_.count(name) > 0;
    }

private:
    bus::Bus bus_;
    bus::Subscription sub_;
    std::set<std::string> seen_;
};

class LocalCluster {
public:
    // `key_file`: every service signs and verifies with it (empty: no keys).
    explicit LocalCluster(int planners, std::vector<std::string> coordinator_flags = {},
                          std::string key_file = "")
        : url_(unique_url(alive_++)),
          dir_(std::filesystem::temp_directory_path() /
               ("envdesign-e2e-" + std::to_string(getpid()) + "-" + std::to_string(alive_))),
          key_file_(std::move(key_file)),
          watcher_(url_, key_file_.empty() ? nullptr
                                           : std::make_shared<const bus::KeyRing>(
                                                 bus::load_key_file(key_file_))) {
        std::filesystem::create_directories(dir_);
        std::vector<std::string> args = {binary("envdesign-coordinator"),
                                         "--lcm-url",
                                         url_,
                                         "--name",
                                         "coordinator",
                                         "--planner-timeout",
                                         "0.5"};
        args.insert(args.end(), coordinator_flags.begin(), coordinator_flags.end());
        add_key_flag(args);
        coordinator_args_ = args;
        coordinator_ = std::make_unique<Process>(args, (dir_ / "coordinator.log").string());
        for (int i = 0; i < planners; ++i)
            add_planner();
    }

    // Stops the coordinator with `signal` (SIGKILL: mid-write, no goodbye) and starts it
    // again with the same flags; waits until it knows every planner again.
    // `between` runs while no coordinator runs.
    void restart_coordinator(int signal, const std::function<void()> &between = {}) {
        coordinator_->signal(signal);
        coordinator_->wait();
        if (between)
            between();
        std::string log = "coordinator-" + std::to_string(++restarts_) + ".log";
        coordinator_ = std::make_unique<Process>(coordinator_args_, (dir_ / log).string());
        for (std::size_t i = 0; i < planners_.size(); ++i)
            EXPECT_TRUE(coordinator_knows("planner-" + std::to_string(i)))
                << "planner-" << i << " never joined the restarted coordinator\n"
                << logs();
    }
    ~LocalCluster() {
        --alive_;
        planners_.clear();
        coordinator_.reset();
        if (!::testing::Test::HasFailure())
            std::filesystem::remove_all(dir_);
    }

    // Starts planner "planner-N" and waits until it is heard.
    Process &add_planner(const std::vector<std::string> &flags = {}) {
        std::string name = "planner-" + std::to_string(planners_.size());
        std::vector<std::string> args = {
            binary("envdesign-planner"), "--lcm-url", url_, "--name", name, "--heartbeat", "0.1"};
        args.insert(args.end(), flags.begin(), flags.end());
        add_key_flag(args);
        planners_.push_back(std::make_unique<Process>(args, (dir_ / (name + ".log")).string()));
        EXPECT_TRUE(watcher_.wait_for(name)) << name << " never beat";
        // Heard here is not yet heard by the coordinator, which may still be starting.
        EXPECT_TRUE(coordinator_knows(name)) << name << " never joined\n" << logs();
        return *planners_.back();
    }

    const std::string &url() const { return url_; }
    const std::string &key_file() const { return key_file_; }
    Process &coordinator() { return *coordinator_; }
    Process &planner(int i) { return *planners_.at(i); }
    std::string logs() {
        std::string all = "--- coordinator\n" + coordinator_->output();
        for (std::size_t i = 0; i < planners_.size(); ++i)
            all += "--- planner-" + std::to_string(i) + "\n" + planners_[i]->output();
        return all;
    }

private:
    void add_key_flag(std::vector<std::string> &args) const {
        if (!key_file_.empty()) {
            args.push_back("--key-file");
            args.push_back(key_file_);
        }
    }
    // True once the coordinator logged that `name` joined.
    bool coordinator_knows(const std::string &name, double timeout_s = 10) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
        std::string joined = "planner " + name + " joined";
        while (std::chrono::steady_clock::now() < end) {
            if (coordinator_->output().find(joined) != std::string::npos)
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return false;
    }

    static inline int alive_ = 0; // clusters of this process at once: each has its own port
    std::string url_;
    std::filesystem::path dir_;
    std::string key_file_;
    HeartbeatWatcher watcher_;
    std::vector<std::string> coordinator_args_;
    int restarts_ = 0;
    std::unique_ptr<Process> coordinator_;
    std::vector<std::unique_ptr<Process>> planners_;
};

// The planners' own counts, from their heartbeats: jobs computed (jobs_done) and held.
class HeartbeatTally {
public:
    explicit HeartbeatTally(const std::string &url)
        : bus_(url, std::make_shared<spdlog::logger>(
                        "tally", std::make_shared<spdlog::sinks::null_sink_mt>())) {
        sub_ = bus_.subscribe<envdesign::planner_heartbeat_t>(
            bus::HEARTBEAT, [this](const envdesign::planner_heartbeat_t &b) {
                last_[b.sender] = {b.jobs_done, b.num_jobs};
                ++beats_;
            });
    }
    // Listens until `done` returns true (or `timeout_s` passes); true if it did.
    bool until(const std::function<bool()> &done, double timeout_s = 60) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
        while (!done() && std::chrono::steady_clock::now() < end)
            bus_.handle(std::chrono::milliseconds(5));
        return done();
    }
    // Listens for `seconds` (the last heartbeats of work just finished).
    void settle(double seconds = 0.5) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        until([&] { return std::chrono::steady_clock::now() >= end; });
    }
    long long done() const {
        long long total = 0;
        for (const auto &[name, counts] : last_)
            total += counts.first;
        return total;
    }
    long long held() const {
        long long total = 0;
        for (const auto &[name, counts] : last_)
            total += counts.second;
        return total;
    }
    long long beats() const { return beats_; }

private:
    bus::Bus bus_;
    bus::Subscription sub_;
    std::map<std::string, std::pair<long long, long long>> last_;
    long long beats_ = 0;
};

// `envdesign design SPEC --connect URL --json` in the background (the CLI re-sends the
// request when it hears nothing, e.g. across a coordinator's restart).
class CliRun {
public:
    CliRun(const std::string &url, const std::string &spec, const std::filesystem::path &dir,
           const std::string &name)
        : out_(dir / (name + ".json")),
          process_({"/bin/bash", "-c",
                    binary("envdesign") + " design " + spec + " --json --connect '" + url + "' > " +
                        out_.string()},
                   (dir / (name + ".log")).string()) {}
    bool running() { return process_.running(); }
    nlohmann::json result() {
        auto code = process_.wait(std::chrono::seconds(120));
        EXPECT_EQ(code, std::optional<int>(0)) << process_.output();
        std::ifstream in(out_);
        return nlohmann::json::parse(in);
    }

private:
    std::filesystem::path out_;
    Process process_;
};

// Records in a coordinator's evaluation file (common/store/record_db.h), read as another
// program would: each is an answer the coordinator had received and written.
inline long long stored_records(const std::filesystem::path &file) {
    sqlite3 *db = nullptr;
    long long n = -1;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK) {
        sqlite3_stmt *count = nullptr;
        if (sqlite3_prepare_v2(db, "SELECT count(*) FROM records", -1, &count, nullptr) ==
                SQLITE_OK &&
            sqlite3_step(count) == SQLITE_ROW)
            n = sqlite3_column_int64(count, 0);
        sqlite3_finalize(count);
    }
    sqlite3_close(db);
    return n;
}

// What a shell command prints on stdout; `exit_code` gets its exit code.
inline std::string command_output(const std::string &command, int *exit_code = nullptr) {
    FILE *out = popen(command.c_str(), "r");
    std::string text;
    char buffer[4096];
    while (out && fgets(buffer, sizeof buffer, out))
        text += buffer;
    int status = out ? pclose(out) : -1;
    if (exit_code)
        *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return text;
}

// `envdesign design SPEC --json`: the self-contained run.
inline nlohmann::json self_contained(const std::string &spec) {
    return nlohmann::json::parse(
        command_output(binary("envdesign") + " design " + spec + " --json 2>/dev/null"));
}

// The fields of SPEC.md's result that do not depend on how the work was spread.
// (Counts of configurations depend on the order answers come back in, and on the search.)
inline void expect_same_design(const nlohmann::json &got, const nlohmann::json &want) {
    for (const char *key :
         {"status", "design", "objective", "terms", "baseline", "tasks", "limit_reached"})
        EXPECT_EQ(got.at(key), want.at(key)) << key;
    // The explanation travels too (design_result_t): per task, plans and marginal values.
    for (const char *key : {"weighted_terms", "least_inexplicability"})
        EXPECT_EQ(got.value(key, nlohmann::json()), want.value(key, nlohmann::json())) << key;
    if (want.contains("explanation")) {
        for (const char *key : {"tasks", "marginal"})
            EXPECT_EQ(got.at("explanation").at(key), want.at("explanation").at(key)) << key;
    }
}

// `envdesign design` of the restaurant through the cluster at `url`: exit 0 and the
// self-contained run's design (`logs`: the cluster's, shown on a failure).
inline void expect_connect_gives_self_contained(const std::string &url, const std::string &logs) {
    int exit_code = -1;
    std::string json = command_output(binary("envdesign") + " design " + source(RESTAURANT) +
                                          " --json --connect '" + url + "' 2>/dev/null",
                                      &exit_code);
    ASSERT_EQ(exit_code, 0) << json << logs;
    expect_same_design(nlohmann::json::parse(json), self_contained(source(RESTAURANT)));
}

} // namespace envdesign::e2e
