// envdesign-arrivals --replay FILE reads its file as every input file is read
// (pddl/input_file.h): a device, a FIFO or a directory is bad input (exit 2, the path named)
// instead of a read that never ends, and a problem file named in a cell is checked the same
// way with the cell's FILE:LINE:COL.

#include "harness.h"

#include <sys/stat.h>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

struct Outcome {
    std::optional<int> code;
    std::string output;
};

Outcome replay(const std::string &dir, const std::string &file) {
    Process p({BIN + "/envdesign-arrivals", "--replay", file, "--problem", "restaurant", "--domain",
               "78"},
              dds_env(), dir + "/arrivals.log");
    auto code = p.wait(10s); // a FIFO or /dev/zero would block or grow forever
    return {code, p.output()};
}

TEST(ReplayFile, DevicesFifosAndDirectoriesAreBadInput) {
    std::string dir = scratch("replay-file");
    Outcome zero = replay(dir, "/dev/zero");
    EXPECT_EQ(zero.code, std::optional<int>(2)) << zero.output;
    EXPECT_NE(zero.output.find("/dev/zero: error: not a regular file"), std::string::npos)
        << zero.output;
    std::string fifo = dir + "/fifo.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    Outcome f = replay(dir, fifo);
    EXPECT_EQ(f.code, std::optional<int>(2)) << f.output;
    EXPECT_NE(f.output.find(fifo + ": error: not a regular file"), std::string::npos) << f.output;
    Outcome d = replay(dir, dir);
    EXPECT_EQ(d.code, std::optional<int>(2)) << d.output;
    EXPECT_NE(d.output.find(dir + ": error: not a regular file"), std::string::npos) << d.output;
}

TEST(ReplayFile, AProblemFileThatIsADirectoryIsNamedAtItsCell) {
    std::string dir = scratch("replay-problem");
    std::filesystem::create_directories(dir + "/tasks");
    std::string csv = write_replay(dir + "/new.csv", "task,problem_file", {"serve-g3,tasks"});
    Outcome r = replay(dir, csv);
    EXPECT_EQ(r.code, std::optional<int>(2)) << r.output;
    EXPECT_NE(r.output.find(csv + ":2:10: error: cannot read '" + dir + "/tasks': "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
}

} // namespace
} // namespace envdesign::testing
