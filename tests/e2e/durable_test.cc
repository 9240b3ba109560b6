// Durable evaluations (issue 11) with real processes: a coordinator with --state-dir and two
// planners; the coordinator SIGKILLed in the middle of a search and started again on the
// same state directory; the client (the CLI, re-sending on silence) gets the undisturbed
// design, and work answered before the kill is not done again.

#include "local_cluster.h"

#include <sqlite3.h>

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
    long long stored_at_kill = -1;
    ASSERT_TRUE(client.running()) << "the search ended before the kill";
    fs::path file = dir / "killed" / "evaluations.db";
    cluster.restart_coordinator(SIGKILL, [&] { stored_at_kill = stored_records(file); });
    nlohmann::json got = client.result();
    tally.settle();
    // Every job the restarted coordinator sent was for something not stored: each added a
    // record (a job for a stored evaluation would add none).
    auto counters = got.at("cluster");
    long long new_jobs =
        counters.at("jobs_sent").get<long long>() - counters.at("jobs_resent").get<long long>();
    EXPECT_GT(stored_at_kill, done_at_kill / 2);
    EXPECT_EQ(stored_records(file) - stored_at_kill, new_jobs);

    expect_same_design(got, want);
    long long sent_after = got.at("cluster").at("jobs_sent");
    std::cout << "undisturbed " << undisturbed << " jobs; killed after " << done_at_kill << " with "
              << in_flight << " in flight; the restarted coordinator sent " << sent_after
              << "; the planners computed " << tally.done() << " in all; " << stored_at_kill
              << " evaluations were stored at the kill\n";
    // What was answered before the kill is not asked again; what was in flight may be. The
    // witness search's job count itself varies by about 1% between undisturbed runs (two
    // planners race, and answers steer the search), so the bounds allow 5% beside the jobs
    // in flight; a coordinator that lost its evaluations would send about `undisturbed`
    // jobs again after the kill, half of them too many.
    long long slack = undisturbed / 20;
    EXPECT_LE(done_at_kill + sent_after, undisturbed + in_flight + slack);
    // The planners compute nothing twice: jobs the dead coordinator had in flight are
    // answered from their memory when the restarted one sends them again.
    EXPECT_LE(tally.done(), undisturbed + in_flight + slack);

    // A clean restart: the repeat is answered from the file alone.
    cluster.restart_coordinator(SIGTERM);
    nlohmann::json repeat = CliRun(cluster.url(), source(BLOCKS), dir, "repeat").result();
    expect_same_design(repeat, want);
    EXPECT_EQ(repeat.at("cluster").at("jobs_sent"), 0);
    EXPECT_NE(cluster.logs().find("stored evaluations in"), std::string::npos);
}

// A state file that is not ours is never read: the coordinator sets it aside, says so, and
// serves from an empty one.
TEST_F(DurableTest, AStateFileThatIsNotAStoreIsSetAsideAtStart) {
    std::ofstream(dir / "killed" / "evaluations.db") << "SQLite format 3 but not really\n";
    LocalCluster cluster(1, {"--state-dir", (dir / "killed").string()});
    nlohmann::json got =
        CliRun(cluster.url(), source("examples/restaurant/c-two-tasks-t10.textproto"), dir, "run")
            .result();
    EXPECT_EQ(got.at("status"), "optimal");
    EXPECT_GT(got.at("cluster").at("jobs_sent"), 0);
    EXPECT_NE(cluster.logs().find("could not be trusted"), std::string::npos) << cluster.logs();
    int set_aside = 0;
    for (const auto &entry : fs::directory_iterator(dir / "killed"))
        set_aside += entry.path().filename().string().starts_with("evaluations.db.corrupt-");
    EXPECT_EQ(set_aside, 1);
}

// Rows changed in place, `sql` run on the closed file; returns the rows changed.
long long edit_store(const fs::path &file, const std::string &sql) {
    sqlite3 *db = nullptr;
    long long changed = -1;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK &&
        sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK)
        changed = sqlite3_changes(db);
    sqlite3_close(db);
    return changed;
}

// Issue 21: values changed inside evaluations.db (the file still passes SQLite's integrity
// check) gave wrong designs marked optimal (a NaN or 0 IE) or aborted every start (a bound
// of 1e308). Now every record carries a tag over its bytes and its values are checked when
// read: a changed record is deleted, counted, and planned again.
// A record's value: version, kind ('E' evaluation, 'B' bound), then for 'E' the status and
// the IE as 8 little-endian bytes, for 'B' the bound. Each case sets every IE to one value
// and every bound to another (hex of the 8 bytes).
struct StoreEdit {
    const char *name, *ie, *bound;
};

void PrintTo(const StoreEdit &e, std::ostream *out) { *out << e.name; }

class StoreEdits : public DurableTest, public ::testing::WithParamInterface<StoreEdit> {};

// The coordinator's count of the store's bad records in its status (`envdesign status
// --json`): -1 if it has none, -2 if no coordinator was heard.
long long bad_records_in_status(const std::string &url) {
    int exit_code = -1;
    std::string lines = command_output(
        binary("envdesign") + " status --json --connect '" + url + "' --seconds 1.5", &exit_code);
    std::istringstream in(lines);
    for (std::string line; std::getline(in, line);) {
        auto j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_discarded() || j.value("kind", "") != "coordinator")
            continue;
        for (const auto &drop : j.at("drops"))
            if (drop.at("channel") == "store:evaluations.db" && drop.at("reason") == "bad-record")
                return drop.at("count").get<long long>();
        return -1;
    }
    return -2;
}

TEST_P(StoreEdits, AreDroppedAndCountedNeverUsed) {
    fs::path state = dir / "killed";
    LocalCluster cluster(1, {"--state-dir", state.string()});
    nlohmann::json want = CliRun(cluster.url(), source(RESTAURANT), dir, "first").result();
    ASSERT_EQ(want.at("status"), "optimal");
    EXPECT_EQ(bad_records_in_status(cluster.url()), -1); // nothing bad read yet
    const StoreEdit &edit = GetParam();
    long long evaluations = -1, bounds = -1;
    cluster.restart_coordinator(SIGTERM, [&] {
        evaluations = edit_store(state / "evaluations.db",
                                 "UPDATE records SET value = CAST(substr(value, 1, 3) || X'" +
                                     std::string(edit.ie) +
                                     "' || substr(value, 12) AS BLOB) WHERE "
                                     "hex(substr(value, 2, 1)) = '45'"); // 'E'
        bounds = edit_store(state / "evaluations.db",
                            "UPDATE records SET value = CAST(substr(value, 1, 2) || X'" +
                                std::string(edit.bound) +
                                "' || substr(value, 11) AS BLOB) WHERE "
                                "hex(substr(value, 2, 1)) = '42'"); // 'B'
    });
    // The restaurant's search stores both kinds (14 of each): every case edits some of each.
    ASSERT_GT(evaluations, 0);
    ASSERT_GT(bounds, 0);
    nlohmann::json repeat = CliRun(cluster.url(), source(RESTAURANT), dir, "after").result();
    expect_same_design(repeat, want);
    EXPECT_GT(repeat.at("cluster").at("jobs_sent"), 0); // planned again, not read
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_NE(cluster.logs().find("failed their check (tag or values) and were deleted"),
              std::string::npos)
        << cluster.logs();
    // The same search reads every record it stored: each edited one is counted once.
    EXPECT_EQ(bad_records_in_status(cluster.url()), evaluations + bounds) << cluster.logs();
}

INSTANTIATE_TEST_SUITE_P(
    Issue21, StoreEdits,
    ::testing::Values(StoreEdit{"IeNanBound1e308", "000000000000F87F", "A0C8EB85F3CCE17F"},
                      StoreEdit{"IeZeroBoundNan", "0000000000000000", "000000000000F87F"},
                      StoreEdit{"IeZeroBoundInf", "0000000000000000", "000000000000F07F"}));

} // namespace
} // namespace envdesign::e2e
