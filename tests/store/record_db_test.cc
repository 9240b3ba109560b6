// The durable record store on real SQLite files: persistence, what is set aside, eviction,
// and a SIGKILL in the middle of writing.

#include "store/record_db.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace envdesign::store {
namespace {

namespace fs = std::filesystem;

Digest key(int i) { return sha256("test record v1 " + std::to_string(i)); }
std::string value(int i) { return "value " + std::to_string(i) + std::string(100, 'x'); }

class RecordDbTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("envdesign-store-" + std::to_string(getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        path = (dir / "evaluations.db").string();
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir);
    }
    // Runs `sql` on the file with plain SQLite, as another program would.
    void sql(const std::string &statement) {
        sqlite3 *db = nullptr;
        ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(db, statement.c_str(), nullptr, nullptr, nullptr), SQLITE_OK)
            << sqlite3_errmsg(db);
        sqlite3_close(db);
    }
    std::vector<fs::path> set_aside_files() const {
        std::vector<fs::path> found;
        for (const auto &entry : fs::directory_iterator(dir))
            if (entry.path().filename().string().find(".corrupt-") != std::string::npos)
                found.push_back(entry.path());
        return found;
    }
    void fill(int n) {
        RecordDbOptions options;
        options.sync = false; // a process kill is what these tests make; no fsync needed
        RecordDb db(path, options);
        for (int i = 0; i < n; ++i)
            db.put(key(i), value(i));
    }

    fs::path dir;
    std::string path;
};

TEST(Digest, IsSha256) {
    EXPECT_EQ(sha256("abc").hex(),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST_F(RecordDbTest, RecordsSurviveReopening) {
    {
        RecordDb db(path, {});
        EXPECT_TRUE(db.report().created);
        for (int i = 0; i < 50; ++i)
            db.put(key(i), value(i));
        db.put(key(3), "another value"); // a record once written keeps its value
        EXPECT_EQ(db.records(), 50u);
    }
    RecordDb db(path, {});
    EXPECT_FALSE(db.report().created);
    EXPECT_TRUE(db.report().set_aside.empty());
    EXPECT_EQ(db.report().records, 50u);
    for (int i = 0; i < 50; ++i)
        EXPECT_EQ(db.get(key(i)), value(i)) << i;
    EXPECT_FALSE(db.get(key(50)));
}

TEST_F(RecordDbTest, AFileThatIsNotSqliteIsSetAside) {
    std::ofstream(path) << "these are not the records you are looking for\n";
    RecordDb db(path, {});
    EXPECT_TRUE(db.report().created);
    EXPECT_NE(db.report().reason.find("bad header"), std::string::npos) << db.report().reason;
    ASSERT_EQ(set_aside_files().size(), 1u);
    EXPECT_EQ(set_aside_files()[0].string(), db.report().set_aside);
    std::ifstream kept(db.report().set_aside);
    std::string line;
    std::getline(kept, line);
    EXPECT_EQ(line, "these are not the records you are looking for"); // kept as it was
    db.put(key(1), value(1));
    EXPECT_EQ(db.get(key(1)), value(1));
}

TEST_F(RecordDbTest, DamagedPagesAreSetAsideNotTrusted) {
    fill(2000); // several pages of records
    auto size = fs::file_size(path);
    ASSERT_GT(size, 8 * 4096u);
    {
        std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(4096); // the header page stays: SQLite opens the file, the tree is garbage
        std::string garbage(size - 4096, '\x5a');
        file.write(garbage.data(), static_cast<std::streamsize>(garbage.size()));
    }
    RecordDb db(path, {});
    EXPECT_TRUE(db.report().created);
    EXPECT_FALSE(db.report().set_aside.empty());
    EXPECT_EQ(db.records(), 0u);
    EXPECT_FALSE(db.get(key(5)));
    EXPECT_EQ(set_aside_files().size(), 1u);
}

TEST_F(RecordDbTest, AForeignDatabaseIsSetAside) {
    sql("CREATE TABLE inventory (item TEXT, count INTEGER); INSERT INTO inventory VALUES ('a', "
        "1)");
    RecordDb db(path, {});
    EXPECT_NE(db.report().reason.find("foreign"), std::string::npos) << db.report().reason;
    EXPECT_EQ(set_aside_files().size(), 1u);
    EXPECT_EQ(db.records(), 0u);
}

TEST_F(RecordDbTest, AnotherApplicationsIdIsSetAside) {
    fill(3);
    sql("PRAGMA application_id = 1234");
    RecordDb db(path, {});
    EXPECT_NE(db.report().reason.find("application_id"), std::string::npos);
    EXPECT_FALSE(db.get(key(1)));
}

TEST_F(RecordDbTest, AnotherFormatVersionIsSetAside) {
    fill(3);
    sql("PRAGMA user_version = " + std::to_string(RecordDb::FORMAT_VERSION + 1));
    RecordDb db(path, {});
    EXPECT_NE(db.report().reason.find("format version"), std::string::npos) << db.report().reason;
    EXPECT_FALSE(db.get(key(1)));
    EXPECT_EQ(set_aside_files().size(), 1u);
}

TEST_F(RecordDbTest, AnAlteredSchemaIsSetAside) {
    fill(3);
    sql("ALTER TABLE records ADD COLUMN extra TEXT");
    RecordDb db(path, {});
    EXPECT_NE(db.report().reason.find("schema"), std::string::npos) << db.report().reason;
    EXPECT_FALSE(db.get(key(1)));
}

// Issue 21: a value changed inside the file (which still passes SQLite's integrity check)
// was used as it was. Its tag no longer matches: deleted, counted, never returned; the
// name can be written again.
TEST_F(RecordDbTest, AChangedValueIsRejectedCountedAndCanBeWrittenAgain) {
    fill(5);
    sql("UPDATE records SET value = CAST('V' AS BLOB) || substr(value, 2) WHERE "
        "hex(substr(value, 1, 7)) = hex('value 1')");
    RecordDb db(path, {});
    EXPECT_EQ(db.records(), 5u);
    EXPECT_FALSE(db.get(key(1)));
    EXPECT_EQ(db.rejected(), 1);
    EXPECT_EQ(db.records(), 4u);
    EXPECT_EQ(db.get(key(2)), value(2));
    db.put(key(1), value(1));
    EXPECT_EQ(db.get(key(1)), value(1));
    EXPECT_EQ(db.rejected(), 1);
}

TEST_F(RecordDbTest, ARecordMovedToAnotherNameIsRejected) {
    fill(2);
    // The value (and its tag) of record 0 copied over record 1's: the tag covers the name.
    sql("UPDATE records SET value = (SELECT value FROM records WHERE hex(substr(value, 1, 7)) = "
        "hex('value 0')) WHERE hex(substr(value, 1, 7)) = hex('value 1')");
    RecordDb db(path, {});
    EXPECT_EQ(db.get(key(0)), value(0));
    EXPECT_FALSE(db.get(key(1)));
    EXPECT_EQ(db.rejected(), 1);
}

TEST_F(RecordDbTest, KeyedTagsVerifyWithAnyKeyOfTheRingAndNotWithoutOne) {
    RecordDbOptions old_key;
    old_key.secrets = {"old secret"};
    {
        RecordDb db(path, old_key);
        db.put(key(1), value(1));
        db.put(key(2), value(2));
    }
    RecordDbOptions rotated; // a new key signs, the old one still verifies
    rotated.secrets = {"new secret", "old secret"};
    {
        RecordDb db(path, rotated);
        EXPECT_EQ(db.get(key(1)), value(1));
        db.put(key(3), value(3));
    }
    RecordDbOptions unkeyed; // the checksum is not the MAC: a writer without the key fails
    RecordDb db(path, unkeyed);
    EXPECT_FALSE(db.get(key(2)));
    EXPECT_FALSE(db.get(key(3)));
    EXPECT_EQ(db.rejected(), 2);
}

// Format 1 kept values without tags; its records are tagged at open, not lost.
TEST_F(RecordDbTest, AFormatOneFileIsTaggedAtOpen) {
    { RecordDb db(path, {}); }
    sql("PRAGMA user_version = 1");
    sqlite3 *raw = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
    sqlite3_stmt *insert = nullptr;
    ASSERT_EQ(
        sqlite3_prepare_v2(raw, "INSERT INTO records VALUES (?1, ?2, 1)", -1, &insert, nullptr),
        SQLITE_OK);
    Digest k = key(7);
    std::string v = value(7);
    sqlite3_bind_blob(insert, 1, k.bytes.data(), static_cast<int>(k.bytes.size()), SQLITE_STATIC);
    sqlite3_bind_blob(insert, 2, v.data(), static_cast<int>(v.size()), SQLITE_STATIC);
    ASSERT_EQ(sqlite3_step(insert), SQLITE_DONE);
    sqlite3_finalize(insert);
    sqlite3_close(raw);
    {
        RecordDb db(path, {});
        EXPECT_TRUE(db.report().set_aside.empty()) << db.report().reason;
        EXPECT_EQ(db.get(key(7)), value(7));
    }
    RecordDb again(path, {});
    EXPECT_EQ(again.get(key(7)), value(7));
    EXPECT_EQ(again.rejected(), 0);
}

TEST_F(RecordDbTest, EvictsTheLeastRecentlyUsedPastTheBound) {
    RecordDbOptions options;
    options.max_records = 20;
    {
        RecordDb db(path, options);
        for (int i = 0; i < 20; ++i)
            db.put(key(i), value(i));
        EXPECT_EQ(db.get(key(0)), value(0)); // 0 is now the most recently used
        for (int i = 20; i < 30; ++i)
            db.put(key(i), value(i));
        EXPECT_LE(db.records(), 20u);
        EXPECT_GT(db.evicted(), 0);
        EXPECT_TRUE(db.get(key(0)));
        EXPECT_FALSE(db.get(key(1))); // the oldest untouched go first
        EXPECT_TRUE(db.get(key(29)));
    }
    RecordDb db(path, options);
    EXPECT_LE(db.report().records, 20u);
    EXPECT_TRUE(db.get(key(0))); // the last use was written at close
}

TEST_F(RecordDbTest, EvictsPastTheByteBound) {
    RecordDbOptions options;
    options.sync = false;
    options.max_bytes = 50 * (32 + value(0).size() + 32); // key, value, tag
    RecordDb db(path, options);
    for (int i = 0; i < 200; ++i)
        db.put(key(i), value(i));
    EXPECT_LE(db.bytes(), options.max_bytes);
    EXPECT_GE(db.records(), 40u);
    EXPECT_TRUE(db.get(key(199)));
}

// A writer killed at a random instant: every record whose put() had returned is there, and
// the file opens clean.
TEST_F(RecordDbTest, EveryAcknowledgedRecordSurvivesSigkill) {
    for (int round = 0; round < 3; ++round) {
        int pipe_fds[2];
        ASSERT_EQ(pipe(pipe_fds), 0);
        pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            close(pipe_fds[0]);
            RecordDbOptions options;
            options.sync = round % 2 == 0;
            RecordDb db(path, options);
            for (int i = round * 100000;; ++i) {
                db.put(key(i), value(i));
                if (write(pipe_fds[1], &i, sizeof i) != sizeof i) // acknowledged
                    _exit(1);
            }
        }
        close(pipe_fds[1]);
        int last = -1, got = 0;
        for (int n = 0; n < 200 + 150 * round && read(pipe_fds[0], &got, sizeof got) == sizeof got;
             ++n)
            last = got;
        kill(child, SIGKILL);
        while (read(pipe_fds[0], &got, sizeof got) == sizeof got)
            last = got; // acknowledged before the kill landed
        close(pipe_fds[0]);
        waitpid(child, nullptr, 0);
        ASSERT_GE(last, round * 100000);
        RecordDb db(path, {});
        EXPECT_TRUE(db.report().set_aside.empty()) << db.report().reason;
        for (int i = round * 100000; i <= last; ++i)
            ASSERT_EQ(db.get(key(i)), value(i)) << "round " << round << " record " << i;
    }
}

} // namespace
} // namespace envdesign::store
