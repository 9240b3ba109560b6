#pragma once
// Shared by the real-process tests of the bridge: paths, the loopback DDS configuration,
// replay files, and starting the bridge, the publisher, the coordinator and planners.

#include "../support/process.h"
#include "listener.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace envdesign::testing {

inline const std::string BIN = ENVDESIGN_BIN_DIR;
inline const std::string SOURCE = ENVDESIGN_SOURCE_DIR;
inline const std::string DRIFT_SPEC = SOURCE + "/tests/arrivals/data/restaurant-drift.textproto";

// Every child process talks DDS on loopback only (deploy/cyclonedds-loopback.xml).
inline std::vector<std::string> dds_env() {
    return {"CYCLONEDDS_URI=file://" + SOURCE + "/deploy/cyclonedds-loopback.xml"};
}

// Tests isolate LCM by port (PLATFORM.md §3) and DDS by domain id. ctest runs the tests of
// this folder in parallel, so each test has its own pair, 77NN and NN, unique in tests/
// (two tests once shared 7766/66 and 7779/79, and failed now and then under load).
inline std::string lcm_url(int port) {
    return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

// The self-contained run's JSON result (`envdesign design --json`) for the spec at
// `spec_path` (a file under tests/, its PDDL paths relative to the source tree) with the
// task probabilities set to `d`: the independent answer the bridge's design is checked by.
inline nlohmann::json self_contained(const std::string &dir, const std::string &spec_path,
                                     const std::map<std::string, double> &d) {
    std::ifstream in(spec_path);
    std::stringstream text;
    text << in.rdbuf();
    std::string spec =
        std::regex_replace(text.str(), std::regex("\"\\.\\./\\.\\./\\.\\./"), "\"" + SOURCE + "/");
    std::stringstream lines(spec);
    spec.clear();
    for (std::string line; std::getline(lines, line);) {
        for (const auto &[task, p] : d)
            if (line.find("name: \"" + task + "\"") != std::string::npos)
                line = std::regex_replace(line, std::regex("probability: [0-9.]+"),
                                          "probability: " + std::to_string(p));
        spec += line + "\n";
    }
    std::string path = dir + "/self-contained.textproto";
    std::ofstream(path) << spec;
    std::string out;
    FILE *pipe = popen((BIN + "/envdesign design " + path + " --json 2>/dev/null").c_str(), "r");
    char buffer[4096];
    while (pipe && fgets(buffer, sizeof buffer, pipe))
        out += buffer;
    if (pipe)
        pclose(pipe);
    return nlohmann::json::parse(out);
}

// A scratch directory for one test's logs and replay files.
inline std::string scratch(const std::string &name) {
    auto dir = std::filesystem::path(::testing::TempDir()) / ("bridge-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

// A replay file: `header` then one row a line.
inline std::string write_replay(const std::string &path, const std::string &header,
                                const std::vector<std::string> &rows) {
    std::ofstream out(path);
    out << header << "\n";
    for (const auto &r : rows)
        out << r << "\n";
    return path;
}

// `count` arrivals in blocks of ten: `first` of serve-g1, then serve-g2, so any window of
// a multiple of ten arrivals holds exactly that mix.
inline std::vector<std::string> booth_mix(int count, int first) {
    std::vector<std::string> rows;
    for (int i = 0; i < count; ++i)
        rows.push_back(i % 10 < first ? "serve-g1" : "serve-g2");
    return rows;
}

inline std::unique_ptr<Process> start_bridge(const std::string &dir, int domain, int port,
                                             std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {BIN + "/envdesign-bridge",
                                     "--problem",
                                     "restaurant=" + DRIFT_SPEC,
                                     "--domain",
                                     std::to_string(domain),
                                     "--lcm-url",
                                     lcm_url(port),
                                     "--name",
                                     "bridge/test"};
    if (std::find(extra.begin(), extra.end(), "--publish-hz") == extra.end())
        argv.insert(argv.end(), {"--publish-hz", "50"});
    argv.insert(argv.end(), extra.begin(), extra.end());
    return std::make_unique<Process>(argv, dds_env(), dir + "/bridge.log");
}

// Publishes a replay file for problem "restaurant" and waits for it to finish.
inline int publish(const std::string &dir, const std::string &replay, int domain,
                   std::vector<std::string> extra = {}, const std::string &site = "dock-1") {
    std::vector<std::string> argv = {BIN + "/envdesign-arrivals",
                                     "--replay",
                                     replay,
                                     "--problem",
                                     "restaurant",
                                     "--site",
                                     site,
                                     "--domain",
                                     std::to_string(domain),
                                     "--wait-bridge",
                                     "20"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    Process p(argv, dds_env(),
              dir + "/arrivals-" + std::filesystem::path(replay).stem().string() + ".log");
    auto rc = p.wait(std::chrono::seconds(60));
    EXPECT_TRUE(rc) << "envdesign-arrivals did not finish:\n" << p.output();
    EXPECT_EQ(rc.value_or(-1), 0) << p.output();
    return rc.value_or(-1);
}

// The CPU time (user and system) process `pid` has used so far, seconds (/proc/PID/stat).
inline double cpu_seconds(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Fields from the state on (the third), after the name in parentheses (it may hold spaces):
    // utime and stime are the 14th and 15th.
    std::istringstream fields(stat.substr(stat.rfind(')') + 1));
    std::string skip;
    for (int field = 3; field < 14; ++field)
        fields >> skip;
    long long utime = 0, stime = 0;
    fields >> utime >> stime;
    return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// The estimate's probability of `task` (0 if absent).
inline double probability(const envdesign::task_distribution_t &m, const std::string &task) {
    for (int i = 0; i < m.num_tasks; ++i)
        if (m.tasks[i] == task)
            return m.probabilities[i];
    return 0;
}

inline long long rejected(const envdesign::task_distribution_t &m, const std::string &kind) {
    for (int i = 0; i < m.num_rejected; ++i)
        if (m.rejected_kinds[i] == kind)
            return m.rejected_counts[i];
    return -1;
}

} // namespace envdesign::testing
