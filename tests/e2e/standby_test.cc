// One active coordinator per bus (issue 10), with real processes over loopback: a second
// coordinator started on the same bus hears the first one's status and stands by (it
// started later); a request is answered once, by the first, and only the first sends
// planner jobs. SIGKILL the first: the standby takes over once the first has been silent
// for --takeover-after, and answers the next request with the same design.

#include "local_cluster.h"

#include "envdesign/design_result_t.hpp"
#include "envdesign/job_t.hpp"

#include <envdesign/client/client.h>

#include <map>

namespace envdesign::e2e {
namespace {

using namespace std::chrono_literals;

// Who sent results and jobs on the bus, heard by a thread of the test's own.
class Tally {
public:
    explicit Tally(const std::string &url)
        : bus_(url, std::make_shared<spdlog::logger>(
                        "tally", std::make_shared<spdlog::sinks::null_sink_mt>())) {
        subs_.push_back(bus_.subscribe<envdesign::design_result_t>(
            bus::RESULT, [this](const envdesign::design_result_t &r) {
                std::lock_guard lock(mutex_);
                ++results_[r.sender];
            }));
        subs_.push_back(
            bus_.subscribe<envdesign::job_t>(bus::JOB, [this](const envdesign::job_t &j) {
                std::lock_guard lock(mutex_);
                ++jobs_[j.sender];
            }));
        thread_ = std::thread([this] {
            while (!stop_)
                bus_.handle(20ms);
        });
    }
    ~Tally() {
        stop_ = true;
        thread_.join();
    }
    std::map<std::string, int> results() {
        std::lock_guard lock(mutex_);
        return results_;
    }
    std::map<std::string, int> jobs() {
        std::lock_guard lock(mutex_);
        return jobs_;
    }

private:
    bus::Bus bus_;
    std::vector<bus::Subscription> subs_;
    std::mutex mutex_;
    std::map<std::string, int> results_, jobs_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

TEST(Standby, ASecondCoordinatorStandsByAndTakesOverWhenTheFirstDies) {
    LocalCluster cluster(1, {"--takeover-after", "2"});
    auto dir =
        std::filesystem::temp_directory_path() / ("envdesign-standby-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    Process standby({binary("envdesign-coordinator"), "--lcm-url", cluster.url(), "--name",
                     "coordinator-b", "--planner-timeout", "0.5", "--takeover-after", "2"},
                    (dir / "coordinator-b.log").string());
    ASSERT_TRUE(wait_for_output(standby, "standing by: coordinator coordinator started earlier"))
        << standby.output();
    ASSERT_TRUE(wait_for_output(cluster.coordinator(), "active: no coordinator")) << cluster.logs();
    EXPECT_EQ(cluster.coordinator().output().find("standing by"), std::string::npos);

    Tally tally(cluster.url());
    std::string spec = source(RESTAURANT);
    client::Result first = client::run_design_remote(spec, cluster.url());
    ASSERT_EQ(first.exit_code, 0) << first.error << cluster.logs() << standby.output();
    nlohmann::json want = self_contained(spec);
    expect_same_design(nlohmann::json::parse(first.json), want);
    for (int i = 0; i < 100 && tally.results()["coordinator"] == 0; ++i)
        std::this_thread::sleep_for(20ms); // the tally's thread hears it after the client
    std::this_thread::sleep_for(300ms);    // a second answer would have come by now
    EXPECT_EQ(tally.results(), (std::map<std::string, int>{{"coordinator", 1}}));
    auto jobs = tally.jobs();
    EXPECT_GT(jobs["coordinator"], 0);
    EXPECT_EQ(jobs.count("coordinator-b"), 0u) << "the standby sent planner jobs";
    EXPECT_EQ(standby.output().find("accepted"), std::string::npos) << standby.output();

    cluster.coordinator().signal(SIGKILL);
    ASSERT_TRUE(wait_for_output(standby, "taking over: coordinator coordinator has not been heard"))
        << standby.output();
    client::Result second = client::run_design_remote(spec, cluster.url());
    ASSERT_EQ(second.exit_code, 0) << second.error << standby.output();
    expect_same_design(nlohmann::json::parse(second.json), want);
    for (int i = 0; i < 100 && tally.results()["coordinator-b"] == 0; ++i)
        std::this_thread::sleep_for(20ms); // the tally's thread hears it after the client
    EXPECT_EQ(tally.results()["coordinator-b"], 1);
    EXPECT_EQ(tally.results()["coordinator"], 1);
    standby.signal(SIGTERM);
    EXPECT_EQ(standby.wait(), 0);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace envdesign::e2e
