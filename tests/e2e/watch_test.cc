// `envdesign watch` (issue 13): real services, a real design request, and watchers in their
// own processes that print what passes on the bus, as JSON lines and as text.

#include "local_cluster.h"

namespace envdesign::e2e {
namespace {

// `envdesign watch --lcm-url URL --seconds S [flags]` in the background, stdout to a file.
class Watcher {
public:
    Watcher(const std::string &url, const std::filesystem::path &dir, const std::string &name,
            const std::string &flags)
        : out_(dir / (name + ".out")),
          process_({"/bin/bash", "-c",
                    "exec " + binary("envdesign") + " watch --lcm-url '" + url + "' " + flags +
                        " > " + out_.string()},
                   (dir / (name + ".log")).string()) {}
    // Its exit code once it stopped (within `timeout_s`), and what it printed.
    std::pair<std::optional<int>, std::string> finish(double timeout_s) {
        auto code = process_.wait(std::chrono::milliseconds(static_cast<int>(timeout_s * 1000)));
        std::ifstream in(out_);
        std::stringstream text;
        text << in.rdbuf();
        return {code, text.str()};
    }
    Process &process() { return process_; }
    // True once it printed `text` (within `timeout_s`): e.g. a status line, so it listens.
    bool printed(const std::string &text, double timeout_s = 20) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
        while (std::chrono::steady_clock::now() < end) {
            std::ifstream in(out_);
            std::stringstream all;
            all << in.rdbuf();
            if (all.str().find(text) != std::string::npos)
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }

private:
    std::filesystem::path out_;
    Process process_;
};

std::vector<nlohmann::json> json_lines(const std::string &text) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        auto parsed = nlohmann::json::parse(line, nullptr, false);
        EXPECT_FALSE(parsed.is_discarded()) << "not a JSON line: " << line;
        lines.push_back(parsed);
    }
    return lines;
}

TEST(Watch, PrintsTheProgressAndResultOfARequestAsTheyPass) {
    LocalCluster cluster(1);
    auto dir =
        std::filesystem::temp_directory_path() / ("envdesign-watch-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    // --status: the services' status (1/s) shows when each watcher listens.
    Watcher json(cluster.url(), dir, "json", "--json --status --seconds 60");
    Watcher text(cluster.url(), dir, "text", "--status --seconds 60");
    ASSERT_TRUE(json.printed("\"kind\":\"status\"")) << json.process().output();
    ASSERT_TRUE(text.printed("status coordinator")) << text.process().output();
    CliRun run(cluster.url(), source(RESTAURANT), dir, "design");
    nlohmann::json want = run.result();
    // Ctrl-C (SIGINT) ends a watch cleanly: exit 0, everything printed so far kept.
    json.process().signal(SIGINT);
    text.process().signal(SIGINT);
    auto [json_code, json_out] = json.finish(10);
    auto [text_code, text_out] = text.finish(10);
    EXPECT_EQ(json_code, std::optional<int>(0)) << json.process().output();
    EXPECT_EQ(text_code, std::optional<int>(0)) << text.process().output();

    std::vector<nlohmann::json> results, progress;
    for (const auto &line : json_lines(json_out))
        if (line["kind"] != "status")
            (line["kind"] == "result" ? results : progress).push_back(line);
    ASSERT_EQ(results.size(), 1u) << json_out;
    const nlohmann::json &result = results[0];
    EXPECT_EQ(result["channel"], "ENVDESIGN_RESULT");
    EXPECT_EQ(result["exit_code"], 0);
    // The restaurant (c): the two barriers, 6.513 + 60 + 18.75 = 85.263 (docs/concepts.md),
    // exactly what the requesting client printed.
    EXPECT_EQ(result["result"]["design"], want["design"]);
    EXPECT_EQ(result["result"]["objective"], want["objective"]);
    EXPECT_NEAR(result["result"]["objective"].get<double>(), 85.263216, 1e-6);
    ASSERT_FALSE(progress.empty()) << json_out; // at least twice a second while searching
    for (const auto &p : progress) {
        EXPECT_EQ(p["kind"], "progress");
        EXPECT_EQ(p["request_id"], result["request_id"]);
        EXPECT_EQ(p["client"], result["client"]);
    }
    EXPECT_EQ(progress.back()["state"], "done");
    EXPECT_NE(text_out.find("result " + result["client"].get<std::string>() + "#"),
              std::string::npos)
        << text_out;
    EXPECT_NE(text_out.find("design: {barrier-00-01, barrier-10-11}"), std::string::npos)
        << text_out;
    EXPECT_NE(text_out.find("progress "), std::string::npos) << text_out;
    std::filesystem::remove_all(dir);
}

TEST(Watch, StopsAfterSecondsAndShowsStatusOnRequest) {
    LocalCluster cluster(1);
    auto dir = std::filesystem::temp_directory_path() /
               ("envdesign-watch-status-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    Watcher status(cluster.url(), dir, "status", "--json --status --seconds 2.5");
    auto [code, out] = status.finish(15);
    EXPECT_EQ(code, std::optional<int>(0)) << status.process().output();
    std::set<std::string> services;
    for (const auto &line : json_lines(out)) {
        EXPECT_EQ(line["kind"], "status");
        services.insert(line["name"].get<std::string>());
    }
    // Each service sends its status once a second: both heard within 2.5 s.
    EXPECT_EQ(services, (std::set<std::string>{"coordinator", "planner-0"})) << out;
    std::filesystem::remove_all(dir);
}

// The same JSON error object for bad input found by the coordinator as for bad input found
// in-process: `--json` failures are never only text, whichever path found them.
TEST(JsonErrors, BadInputThroughTheCoordinatorNamesFileLineAndColumn) {
    LocalCluster cluster(1);
    const std::string spec = source("tests/data/design/bad/unknown-action.textproto");
    int exit_code = -1;
    std::string out = command_output(binary("envdesign") + " design " + spec +
                                         " --json --connect '" + cluster.url() + "' 2>/dev/null",
                                     &exit_code);
    EXPECT_EQ(exit_code, 2);
    auto error = nlohmann::json::parse(out, nullptr, false);
    ASSERT_FALSE(error.is_discarded()) << out;
    // Line 6: `  edit { add_precondition { action: "fly" ...`, "fly" at column 43 (the
    // in-process answer, tests/cli).
    EXPECT_EQ(error["exit_code"], 2);
    EXPECT_EQ(error["line"], 6);
    EXPECT_EQ(error["column"], 43);
    EXPECT_NE(error["file"].get<std::string>().find("unknown-action.textproto"), std::string::npos)
        << error;
    EXPECT_EQ(error["error"].get<std::string>().rfind("unknown action 'fly'", 0), 0u) << error;
}

// `envdesign design SPEC --json` through the coordinator of `cluster` and in-process.
struct BothRuns {
    nlohmann::json remote, local;
    int remote_code = -1, local_code = -1;
};

BothRuns design_both_ways(const LocalCluster &cluster, const std::string &spec) {
    BothRuns r;
    r.remote = nlohmann::json::parse(command_output(binary("envdesign") + " design " + spec +
                                                        " --json --connect '" + cluster.url() +
                                                        "' 2>/dev/null",
                                                    &r.remote_code));
    r.local = nlohmann::json::parse(command_output(
        binary("envdesign") + " design " + spec + " --json 2>/dev/null", &r.local_code));
    return r;
}

// Probabilities that do not sum to 1 warn with --connect as in-process: the same line.
TEST(Warnings, ProbabilitiesWarnThroughTheCoordinatorToo) {
    LocalCluster cluster(1);
    const std::string spec = source("tests/data/usability/probabilities-1.1.textproto");
    auto [remote, local, remote_code, local_code] = design_both_ways(cluster, spec);
    EXPECT_EQ(remote_code, 0);
    EXPECT_EQ(local_code, 0);
    ASSERT_EQ(remote["warnings"].size(), 1u) << remote;
    EXPECT_EQ(remote["warnings"], local["warnings"]);
    EXPECT_NE(remote["warnings"][0].get<std::string>().find("sum to 1.1, not 1"),
              std::string::npos);
    EXPECT_EQ(remote["objective"], local["objective"]);
}

// Tasks unsolvable in the unmodified models are named with the reason with --connect too:
// the same lines as in-process (tests/cli/usability_test.cc has their wording).
TEST(Warnings, UnsolvableTasksAreNamedThroughTheCoordinatorToo) {
    LocalCluster cluster(1);
    const std::string spec = source("tests/data/usability/unsolvable-tasks.textproto");
    auto [remote, local, remote_code, local_code] = design_both_ways(cluster, spec);
    EXPECT_EQ(remote_code, local_code);
    ASSERT_GE(local["warnings"].size(), 1u) << local;
    EXPECT_EQ(remote["warnings"], local["warnings"]);
}

TEST(Watch, ABadUrlIsExitTwoWithAJsonError) {
    auto dir = std::filesystem::temp_directory_path() /
               ("envdesign-watch-url-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    Watcher bad("tcp://nowhere", dir, "bad", "--json --seconds 1");
    auto [code, out] = bad.finish(10);
    EXPECT_EQ(code, std::optional<int>(2));
    auto error = nlohmann::json::parse(out, nullptr, false);
    ASSERT_FALSE(error.is_discarded()) << out;
    EXPECT_EQ(error["status"], "error");
    EXPECT_EQ(error["exit_code"], 2);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace envdesign::e2e
