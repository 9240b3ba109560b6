// A planner core on memq answering jobs of two coordinators for the same content: computed
// once (answer_memory.h), each coordinator answered under its own job id.

#include "harness.h"

#include "bus/codec.h"
#include "cluster/planner_memory.h"
#include "cluster/spec_chunks.h"

namespace envdesign::cluster::testing {
namespace {

class PlannerMemoryTest : public ::testing::Test {
protected:
    PlannerMemoryTest() : bus_("memq://", quiet_logger()) {
        PlannerConfig config;
        config.instance = "planner-0";
        planner_ = std::make_unique<Planner>(bus_, config);
        answers_ = bus_.subscribe<envdesign::evaluation_t>(
            bus::EVALUATION, [this](const envdesign::evaluation_t &e) { got_.push_back(e); });
        std::string bytes = bus::encode_message(
            request_of(in_repo("examples/restaurant/c-two-tasks-t10.textproto"), 1).spec);
        hash_ = content_hash(bytes);
        for (const auto &chunk : split_spec(bytes, hash_, 1, "coordinator-a"))
            bus_.publish(bus::SPEC, chunk);
        pump();
    }

    envdesign::job_t job(std::int64_t id, const std::string &coordinator) const {
        envdesign::job_t j{};
        j.request_id = 1;
        j.sender = coordinator;
        j.job_id = id;
        j.planner = "planner-0";
        j.spec_hash = hash_;
        j.kind = envdesign::job_t::KIND_EXPLICABILITY;
        j.task = 1;
        j.modifications = {0};
        j.num_modifications = 1;
        return j;
    }
    // Handles messages until `n` answers came.
    void pump(std::size_t n = 0) {
        auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        do {
            bus_.handle(std::chrono::milliseconds(5));
            planner_->tick();
        } while (got_.size() < n && std::chrono::steady_clock::now() < end);
    }

    bus::Bus bus_;
    std::unique_ptr<Planner> planner_;
    bus::Subscription answers_;
    std::vector<envdesign::evaluation_t> got_;
    std::string hash_;
};

TEST_F(PlannerMemoryTest, TheSameContentIsComputedOnceForAnyCoordinator) {
    bus_.publish(bus::JOB, job(11, "coordinator-a")); // the one that dies
    bus_.publish(bus::JOB, job(22, "coordinator-b")); // its successor, asking the same
    pump(2);
    ASSERT_EQ(got_.size(), 2u);
    std::map<std::int64_t, envdesign::evaluation_t> by_job;
    for (const auto &e : got_)
        by_job[e.job_id] = e;
    ASSERT_TRUE(by_job.count(11) && by_job.count(22));
    EXPECT_EQ(by_job[11].coordinator, "coordinator-a");
    EXPECT_EQ(by_job[22].coordinator, "coordinator-b");
    EXPECT_EQ(by_job[11].status, envdesign::evaluation_t::STATUS_SOLVED);
    EXPECT_EQ(by_job[22].status, by_job[11].status);
    EXPECT_EQ(by_job[22].ie, by_job[11].ie);
    EXPECT_EQ(by_job[22].plan, by_job[11].plan);
    EXPECT_EQ(planner_->stats().jobs_done, 1); // counted before the waiting job's answer
    EXPECT_EQ(planner_->stats().answers_remembered, 1);

    auto other = job(33, "coordinator-c");
    other.task = 0; // another content: computed
    bus_.publish(bus::JOB, other);
    bus_.publish(bus::JOB, job(44, "coordinator-c")); // the first content again: remembered
    pump(4);
    // A job counts as done just after its answer is published.
    auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (planner_->stats().jobs_done < 2 && std::chrono::steady_clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_EQ(planner_->stats().jobs_done, 2);
    EXPECT_EQ(planner_->stats().answers_remembered, 2);
}

// A job's search may hold the limit less its worker's share of the process and the margin;
// a limit the process leaves no room for is 1 byte (the search stops at once), never 0
// ("no limit").
TEST(JobSearchBudget, TheLimitLessTheProcessShareAndTheMargin) {
    constexpr std::size_t MIB = std::size_t{1} << 20;
    EXPECT_EQ(job_search_budget(128 * MIB, 20 * MIB, 1), 128 * MIB - 20 * MIB - JOB_MEMORY_MARGIN);
    EXPECT_EQ(job_search_budget(128 * MIB, 20 * MIB, 2), 128 * MIB - 10 * MIB - JOB_MEMORY_MARGIN);
    EXPECT_EQ(job_search_budget(16 * MIB, 20 * MIB, 1), 1u);
}

} // namespace
} // namespace envdesign::cluster::testing
