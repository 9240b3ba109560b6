// Issue 21, a spec number through --connect: `beta: 1e25` or a modification `cost: 1e24`
// aborted the coordinator in CBC. The coordinator's one full load of a request's spec
// (request_run.cc, Checks::FULL) refuses such a number as that request's error: the CLI exits
// 2 with the spec's line, and the coordinator lives on to answer the next request.

#include "local_cluster.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace envdesign::e2e {
namespace {

namespace fs = std::filesystem;

// A copy of the restaurant spec (and its PDDL files) with `from` replaced by `to` once, in a
// directory of its own; returns the spec's path.
std::string poisoned_spec(const std::string &name, const std::string &from, const std::string &to) {
    fs::path spec = source(RESTAURANT);
    fs::path dir = fs::temp_directory_path() /
                   ("envdesign-poison-spec-" + std::to_string(getpid()) + "-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto &entry : fs::directory_iterator(spec.parent_path()))
        if (entry.path().extension() == ".pddl")
            fs::copy_file(entry.path(), dir / entry.path().filename());
    std::ifstream in(spec);
    std::ostringstream read;
    read << in.rdbuf();
    std::string text = read.str();
    auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    std::string path = (dir / (name + ".textproto")).string();
    std::ofstream(path) << text;
    return path;
}

struct SpecPoison {
    std::string name, from, to;
    int line;         // of the poisoned field in the spec
    std::string says; // in the refusal
};

TEST(Poison, ASpecWithHugeNumbersThroughConnectIsThatRequestsError) {
    LocalCluster cluster(1);
    std::string connect = " --connect '" + cluster.url() + "'";
    const SpecPoison poisons[] = {
        {"beta-1e25", "beta: 30", "beta: 1e25", 37, "beta must be a number in"},
        {"cost-1e24", "name: \"barrier-01-02\" cost: 1", "name: \"barrier-01-02\" cost: 1e24", 13,
         "the cost of modification 'barrier-01-02' must be a number in"},
    };
    for (const SpecPoison &p : poisons) {
        SCOPED_TRACE(p.name);
        std::string spec = poisoned_spec(p.name, p.from, p.to);
        int exit_code = -1;
        std::string out = command_output(
            binary("envdesign") + " design '" + spec + "'" + connect + " 2>&1", &exit_code);
        EXPECT_EQ(exit_code, 2) << out << cluster.logs();
        EXPECT_NE(out.find(spec + ":" + std::to_string(p.line) + ":"), std::string::npos) << out;
        EXPECT_NE(out.find(p.says), std::string::npos) << out;
        // The refusal came from the coordinator (the CLI only bundles the files with
        // --connect): it loaded the request and said why.
        EXPECT_NE(cluster.coordinator().output().find(p.says), std::string::npos) << cluster.logs();
        ASSERT_TRUE(cluster.coordinator().running()) << cluster.logs();
        fs::remove_all(fs::path(spec).parent_path());
    }
    // The next, good, request is answered as the self-contained run answers it.
    expect_connect_gives_self_contained(cluster.url(), cluster.logs());
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
}

} // namespace
} // namespace envdesign::e2e
