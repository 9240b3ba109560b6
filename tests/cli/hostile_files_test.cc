// Input and output files that are not what they should be (issue 10): special files and
// oversized inputs are bad input (exit 2), names that are not UTF-8 do not break --json, and
// output that cannot be written is a failure (exit 1), for the real binary.

#include "run_command.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace envdesign::testing {
namespace {

namespace fs = std::filesystem;

const std::string DOMAIN = DATA + "/tiny/domain.pddl";
const std::string PROBLEM = DATA + "/tiny/problem.pddl";
const std::string EXAMPLES = std::string(ENVDESIGN_TEST_DATA) + "/../../examples/restaurant";

// `envdesign ARGUMENTS` with stderr captured and stdout to `stdout_to` (or captured too),
// killed after 20 s: a hang must fail the test, not stall it.
CommandResult run_bounded(const std::string &arguments, const std::string &stdout_to = "") {
    return run_shell("timeout 20 " + std::string(ENVDESIGN_BIN_DIR) + "/envdesign " + arguments +
                     " 2>&1" + (stdout_to.empty() ? "" : " >" + stdout_to));
}

class HostileFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("envdesign-hostile-" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string &name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

TEST_F(HostileFiles, AFifoIsRefusedNotWaitedFor) {
    std::string fifo = path("domain.pddl");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    auto r = run_bounded("plan " + fifo + " " + PROBLEM);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(fifo + ": error: not a regular file (a FIFO)"), std::string::npos)
        << r.out;
    r = run_bounded("design " + fifo);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    r = run_bounded("validate " + DOMAIN + " " + PROBLEM + " " + fifo);
    EXPECT_EQ(r.exit_code, 2) << r.out;
}

TEST_F(HostileFiles, DevicesAndDirectoriesAreRefused) {
    auto r = run_bounded("plan /dev/zero " + PROBLEM); // was read without bound
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("/dev/zero: error: not a regular file (a device)"), std::string::npos)
        << r.out;
    r = run_bounded("plan " + DOMAIN + " " + dir_.string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("not a regular file (a directory)"), std::string::npos) << r.out;
    r = run_bounded("validate " + DOMAIN + " " + PROBLEM + " /dev/zero");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    r = run_bounded("design /dev/zero");
    EXPECT_EQ(r.exit_code, 2) << r.out;
}

TEST_F(HostileFiles, FilesBeyondTheSizeLimitAreRefused) {
    std::string big = path("big.pddl");
    { std::ofstream(big) << "(define (domain big))"; }
    fs::resize_file(big, (64u << 20) + 1); // sparse: nothing is written
    auto r = run_bounded("plan " + big + " " + PROBLEM);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(big + ": error: the file is larger than 67108864 bytes"),
              std::string::npos)
        << r.out;
}

// Every PDDL file of the restaurant example with object c00 renamed to "c0\xff".
std::string non_utf8_restaurant(const fs::path &dir) {
    for (const auto &entry : fs::directory_iterator(EXAMPLES)) {
        std::ifstream in(entry.path());
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (auto at = text.find("c00"); at != std::string::npos; at = text.find("c00", at))
            text.replace(at, 3, "c0\xff");
        std::ofstream(dir / entry.path().filename()) << text;
    }
    return (dir / "a-one-task-t1.textproto").string();
}

TEST_F(HostileFiles, NamesThatAreNotUtf8DoNotBreakJson) {
    std::string spec = non_utf8_restaurant(dir_);
    auto r = run_bounded("design " + spec + " --json");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("c0\xef\xbf\xbd"), std::string::npos) << r.out; // U+FFFD
    r = run_bounded("plan --json " + path("domain.pddl") + " " + path("serve-g1.pddl"));
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("c0\xef\xbf\xbd"), std::string::npos) << r.out;
    r = run_bounded("explicable --json --robot-domain " + path("domain.pddl") + " --problem " +
                    path("serve-g1.pddl") + " --human-problem " + path("serve-g1-human.pddl"));
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("\"status\":\"solved\""), std::string::npos) << r.out;
}

// A full device: the plan is found, but not written; that is exit 1 with a message.
TEST_F(HostileFiles, WritesToAFullDeviceFail) {
    auto r = run_bounded("plan " + DOMAIN + " " + PROBLEM, "/dev/full");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("cannot write to standard output"), std::string::npos) << r.out;
    r = run_bounded("plan --json " + DOMAIN + " " + PROBLEM, "/dev/full");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    r = run_bounded("plan " + DOMAIN + " " + PROBLEM + " --plan-file /dev/full");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("cannot write '/dev/full': No space left on device"), std::string::npos)
        << r.out;
    r = run_bounded("design " + EXAMPLES + "/a-one-task-t1.textproto --json", "/dev/full");
    EXPECT_EQ(r.exit_code, 1) << r.out;
}

} // namespace
} // namespace envdesign::testing
