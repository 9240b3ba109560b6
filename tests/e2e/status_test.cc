// Health you can see (issue 11): real services publish their status once a second, idle or
// not; `envdesign status` lists them; a client on a bus without a coordinator says so at once.

#include "local_cluster.h"

#include "bus/log.h"
#include "bus/status.h"
#include "envdesign/service_status_t.hpp"

#include <envdesign/client/client.h>

#include <ctime>
#include <iterator>

namespace envdesign::e2e {
namespace {

using envdesign::service_status_t;
using Clock = std::chrono::steady_clock;

// Every status heard on `url` for `seconds`, in order.
std::vector<service_status_t> listen(const std::string &url, double seconds) {
    bus::Bus bus(url, std::make_shared<spdlog::logger>(
                          "listener", std::make_shared<spdlog::sinks::null_sink_mt>()));
    std::vector<service_status_t> heard;
    auto sub = bus.subscribe<service_status_t>(
        bus::STATUS, [&](const service_status_t &s) { heard.push_back(s); });
    auto start = Clock::now();
    while (seconds_since(start) < seconds)
        bus.handle(std::chrono::milliseconds(20));
    return heard;
}

std::vector<service_status_t> of(const std::vector<service_status_t> &all,
                                 const std::string &sender) {
    std::vector<service_status_t> some;
    for (const auto &s : all)
        if (s.sender == sender)
            some.push_back(s);
    return some;
}

TEST(Status, IdleCoordinatorAndPlannersPublishOnceASecond) {
    LocalCluster cluster(2);
    auto heard = listen(cluster.url(), 3.5);
    auto coordinator = of(heard, "coordinator");
    // 3.5 s at 1 Hz: 3 or 4, not the 0 of a silent coordinator nor a flood.
    ASSERT_GE(coordinator.size(), 3u) << cluster.logs();
    EXPECT_LE(coordinator.size(), 5u);
    const service_status_t &last = coordinator.back();
    EXPECT_EQ(last.kind, "coordinator");
    EXPECT_EQ(last.version, bus::version());
    EXPECT_EQ(last.planners, 2);
    EXPECT_EQ(last.requests_open, 0);
    EXPECT_EQ(last.requests_waiting, 0);
    EXPECT_EQ(last.period_ms, 1000);
    EXPECT_GT(last.uptime_s, coordinator.front().uptime_s + 1.5);
    for (std::string planner : {"planner-0", "planner-1"}) {
        auto beats = of(heard, planner);
        ASSERT_GE(beats.size(), 3u) << planner;
        EXPECT_LE(beats.size(), 5u) << planner;
        EXPECT_EQ(beats.back().kind, "planner");
        EXPECT_EQ(beats.back().jobs_done, 0);
    }
}

TEST(Status, CountsWhatTheServicesDid) {
    LocalCluster cluster(2);
    client::Options options;
    options.give_up_after_s = 10;
    client::Result result = client::run_design_remote(source(RESTAURANT), cluster.url(), options);
    ASSERT_EQ(result.exit_code, 0) << result.error << cluster.logs();
    // A message that does not decode is dropped and counted in the coordinator's status.
    {
        bus::Bus garbage(cluster.url(),
                         std::make_shared<spdlog::logger>(
                             "garbage", std::make_shared<spdlog::sinks::null_sink_mt>()));
        garbage.publish_raw(bus::REQUEST, "not a request", 13);
    }
    auto heard = listen(cluster.url(), 2.2);
    auto coordinator = of(heard, "coordinator");
    ASSERT_FALSE(coordinator.empty()) << cluster.logs();
    const service_status_t &c = coordinator.back();
    EXPECT_EQ(c.jobs_done, 1); // one result published
    EXPECT_EQ(c.requests_open, 0);
    EXPECT_EQ(c.jobs_in_flight, 0);
    EXPECT_GT(c.stored_evaluations, 0);
    EXPECT_EQ(c.malformed, 1);
    long long planner_jobs = 0;
    for (std::string planner : {"planner-0", "planner-1"}) {
        auto beats = of(heard, planner);
        ASSERT_FALSE(beats.empty()) << planner;
        planner_jobs += beats.back().jobs_done;
    }
    EXPECT_GT(planner_jobs, 0);
}

TEST(Status, CommandListsTheServices) {
    LocalCluster cluster(2);
    int exit_code = -1;
    std::string table = command_output(binary("envdesign") + " status --connect '" + cluster.url() +
                                           "' --seconds 2.5 2>&1",
                                       &exit_code);
    EXPECT_EQ(exit_code, 0) << table;
    for (const char *name : {"coordinator", "planner-0", "planner-1", "KIND"})
        EXPECT_NE(table.find(name), std::string::npos) << name << " not in\n" << table;

    std::string lines = command_output(binary("envdesign") + " status --json --connect '" +
                                           cluster.url() + "' --seconds 2.5",
                                       &exit_code);
    EXPECT_EQ(exit_code, 0) << lines;
    std::istringstream in(lines);
    std::map<std::string, nlohmann::json> by_name;
    for (std::string line; std::getline(in, line);) {
        auto j = nlohmann::json::parse(line);
        by_name[j["name"]] = j;
    }
    ASSERT_EQ(by_name.size(), 3u) << lines;
    EXPECT_EQ(by_name["coordinator"]["kind"], "coordinator");
    EXPECT_EQ(by_name["coordinator"]["planners"], 2);
    EXPECT_EQ(by_name["planner-1"]["kind"], "planner");
    EXPECT_TRUE(by_name["coordinator"]["drops"].is_array());
}

// Two coordinators on one bus (issue 10): the first active, the second standing by. The
// command shows each one's role and start (started_utime, and as UTC text in both outputs),
// each start between the wall-clock moments around that coordinator's launch.
TEST(Status, CommandShowsEachCoordinatorsRoleAndStart) {
    std::int64_t before = bus::now_utime();
    LocalCluster cluster(1, {"--takeover-after", "2"});
    ASSERT_TRUE(wait_for_output(cluster.coordinator(), "active: no coordinator")) << cluster.logs();
    std::int64_t between = bus::now_utime();
    auto log = std::filesystem::temp_directory_path() /
               ("envdesign-status-b-" + std::to_string(getpid()) + ".log");
    Process standby({binary("envdesign-coordinator"), "--lcm-url", cluster.url(), "--name",
                     "coordinator-b", "--planner-timeout", "0.5", "--takeover-after", "2"},
                    log.string());
    ASSERT_TRUE(wait_for_output(standby, "standing by: coordinator coordinator started earlier"))
        << standby.output();
    std::int64_t after = bus::now_utime();

    int exit_code = -1;
    std::string lines = command_output(binary("envdesign") + " status --json --connect '" +
                                           cluster.url() + "' --seconds 2.5",
                                       &exit_code);
    EXPECT_EQ(exit_code, 0) << lines;
    std::istringstream in(lines);
    std::map<std::string, nlohmann::json> by_name;
    for (std::string line; std::getline(in, line);) {
        auto j = nlohmann::json::parse(line);
        by_name[j["name"]] = j;
    }
    ASSERT_EQ(by_name.size(), 3u) << lines;
    EXPECT_EQ(by_name["coordinator"]["role"], "active");
    EXPECT_EQ(by_name["coordinator-b"]["role"], "standby");
    EXPECT_EQ(by_name["planner-0"]["role"], "");
    std::int64_t a = by_name["coordinator"]["started_utime"];
    std::int64_t b = by_name["coordinator-b"]["started_utime"];
    EXPECT_GE(a, before);
    EXPECT_LE(a, between);
    EXPECT_GE(b, between);
    EXPECT_LE(b, after);
    EXPECT_GE(by_name["planner-0"]["started_utime"].get<std::int64_t>(), before);
    // The text reads back (strptime, timegm) as the second of started_utime.
    for (const char *name : {"coordinator", "coordinator-b", "planner-0"}) {
        std::string text = by_name[name]["started"];
        std::tm tm{};
        const char *end = strptime(text.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm);
        ASSERT_TRUE(end && *end == '\0') << name << ": " << text;
        EXPECT_EQ(static_cast<std::int64_t>(timegm(&tm)),
                  by_name[name]["started_utime"].get<std::int64_t>() / 1000000)
            << name;
    }

    // The table: ROLE and STARTED columns, "-" for a planner's role.
    std::string table = command_output(binary("envdesign") + " status --connect '" + cluster.url() +
                                           "' --seconds 2.5 2>&1",
                                       &exit_code);
    EXPECT_EQ(exit_code, 0) << table;
    std::map<std::string, std::vector<std::string>> rows;
    std::istringstream table_in(table);
    for (std::string line; std::getline(table_in, line);) {
        std::istringstream words(line);
        std::vector<std::string> row{std::istream_iterator<std::string>(words), {}};
        if (row.size() >= 5)
            rows[row[1]] = row;
    }
    ASSERT_TRUE(rows.count("NAME")) << table;
    EXPECT_EQ(rows["NAME"][2], "ROLE");
    EXPECT_EQ(rows["NAME"][4], "STARTED");
    for (auto [name, role] : {std::pair<std::string, std::string>{"coordinator", "active"},
                              {"coordinator-b", "standby"},
                              {"planner-0", "-"}}) {
        ASSERT_TRUE(rows.count(name)) << name << " not in\n" << table;
        EXPECT_EQ(rows[name][2], role) << table;
        EXPECT_EQ(rows[name][4], by_name[name]["started"]) << table;
    }
    standby.signal(SIGTERM);
    EXPECT_EQ(standby.wait(), 0);
    std::filesystem::remove(log);
}

TEST(Status, CommandOnAnEmptyBusSaysNoCoordinator) {
    int exit_code = -1;
    auto start = Clock::now();
    std::string said = command_output(binary("envdesign") + " status --connect '" + unique_url(7) +
                                          "' --seconds 1 2>&1",
                                      &exit_code);
    EXPECT_EQ(exit_code, 1) << said;
    EXPECT_NE(said.find("no coordinator on this bus"), std::string::npos) << said;
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(Status, ClientWithoutCoordinatorFailsWithinTwoSeconds) {
    client::Options options; // the defaults: it would wait 30 s for an answer
    auto start = Clock::now();
    client::Result result = client::run_design_remote(source(RESTAURANT), unique_url(8), options);
    double took = seconds_since(start);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.error.find("no coordinator on this bus"), std::string::npos) << result.error;
    EXPECT_GE(took, 1.9);
    EXPECT_LT(took, 3.0);

    // The CLI says the same.
    int exit_code = -1;
    std::string said = command_output(binary("envdesign") + " design " + source(RESTAURANT) +
                                          " --connect '" + unique_url(8) + "' 2>&1",
                                      &exit_code);
    EXPECT_EQ(exit_code, 1) << said;
    EXPECT_NE(said.find("no coordinator on this bus"), std::string::npos) << said;
}

} // namespace
} // namespace envdesign::e2e
