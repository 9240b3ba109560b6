// Durable evaluations (issue 11) with real processes: a coordinator with --state-dir and two
// planners; the coordinator SIGKILLed in the middle of a search and started again on the
// same state directory; the client (the CLI, re-sending on silence) gets the undisturbed
// design, and work answered before the kill is not done again.

#include "local_cluster.h"

namespace envdesign::e2e {
namespace {

namespace fs = std::filesystem;

// A paper Blocksworld problem (tests/data/paper): a few hundred jobs, seconds on 2 planners.
const char *BLOCKS = "tests/data/paper/blocksworld/12/design-t10.textproto";

class DurableTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("envdesign-durable-" + std::to_string(getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir / "undisturbed");
        fs::create_directories(dir / "killed");
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir);
    }
    fs::path dir;
};

TEST_F(DurableTest, CoordinatorKilledMidSearchResumesFromItsStateDir) {
    nlohmann::json want;
    long long undisturbed = 0; // jobs the planners computed for the whole search
    {
        LocalCluster cluster(2, {"--state-dir", (dir / "undisturbed").string()});
        HeartbeatTally tally(cluster.url());
        want = CliRun(cluster.url(), source(BLOCKS), dir, "undisturbed").result();
        tally.settle();
        undisturbed = tally.done();
        ASSERT_GT(undisturbed, 100);
        EXPECT_EQ(want.at("cluster").at("jobs_sent"), undisturbed); // nothing computed twice
    }

    LocalCluster cluster(2, {"--state-dir", (dir / "killed").string()});
    HeartbeatTally tally(cluster.url());
    CliRun client(cluster.url(), source(BLOCKS), dir, "killed");
    ASSERT_TRUE(tally.until([&] { return tally.done() >= undisturbed / 2; }));
    long long beats = tally.beats(); // kill right after a heartbeat: its counts are current
    ASSERT_TRUE(tally.until([&] { return tally.beats() > beats; }));
    long long done_at_kill = tally.done();
    long long in_flight = tally.held();
    cluster.restart_coordinator(SIGKILL);
    nlohmann::json got = client.result();
    tally.settle();

    expect_same_design(got, want);
    long long sent_after = got.at("cluster").at("jobs_sent");
    std::cout << "undisturbed " << undisturbed << " jobs; killed after " << done_at_kill << " with "
              << in_flight << " in flight; the restarted coordinator sent " << sent_after
              << "; the planners computed " << tally.done() << " in all\n";
    // What was answered before the kill is not asked again; what was in flight may be.
    EXPECT_LE(done_at_kill + sent_after, undisturbed + in_flight);
    EXPECT_LT(sent_after, undisturbed - done_at_kill / 2); // it resumed, not restarted
    // The planners compute nothing twice: jobs the dead coordinator had in flight are
    // answered from their memory when the restarted one sends them again.
    EXPECT_LE(tally.done(), undisturbed + in_flight);

    // A clean restart: the repeat is answered from the file alone.
    cluster.restart_coordinator(SIGTERM);
    nlohmann::json repeat = CliRun(cluster.url(), source(BLOCKS), dir, "repeat").result();
    expect_same_design(repeat, want);
    EXPECT_EQ(repeat.at("cluster").at("jobs_sent"), 0);
    EXPECT_NE(cluster.logs().find("stored evaluations in"), std::string::npos);
}

} // namespace
} // namespace envdesign::e2e
