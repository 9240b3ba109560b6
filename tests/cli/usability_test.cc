// The same behaviour everywhere in the CLI (issue 13): --version, app flags after the
// subcommand, a JSON error object on stdout for every failure under --json, warnings for
// probabilities that do not sum to 1 and for tasks no design can make explicable, JSON spec
// errors at their real line and column, and Ctrl-C printing the best design so far.

#include "run_command.h"

#include "../support/ports.h"
#include "../support/process.h"

#include <envdesign/version.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace envdesign::testing {
namespace {

using nlohmann::json;

// stdout alone, parsed as one JSON document.
json stdout_json(const std::string &arguments, int expected_exit) {
    CommandResult r = run_envdesign(arguments, false);
    EXPECT_EQ(r.exit_code, expected_exit) << r.out;
    json parsed = json::parse(r.out, nullptr, false);
    EXPECT_FALSE(parsed.is_discarded()) << "stdout is not one JSON document:\n" << r.out;
    return parsed;
}

TEST(Version, PrintsNameAndTheProjectVersion) {
    CommandResult r = run_envdesign("--version", false);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out, std::string("envdesign ") + envdesign::VERSION + "\n");
    EXPECT_NE(std::string(envdesign::VERSION).find('.'), std::string::npos);
}

TEST(GlobalFlags, LogLevelWorksBeforeAndAfterTheSubcommand) {
    const std::string plan =
        "plan " + data("bad/ok-domain.pddl") + " " + data("bad/ok-problem.pddl");
    // plan logs its statistics at info: the flag must silence them wherever it is written.
    EXPECT_NE(run_envdesign(plan).out.find("[info]"), std::string::npos);
    CommandResult before = run_envdesign("--log-level off " + plan);
    CommandResult after = run_envdesign(plan + " --log-level off");
    EXPECT_EQ(before.exit_code, 0);
    EXPECT_EQ(after.exit_code, 0);
    EXPECT_EQ(before.out.find("[info]"), std::string::npos) << before.out;
    EXPECT_EQ(after.out.find("[info]"), std::string::npos) << after.out;
    EXPECT_EQ(before.out, after.out);
}

TEST(JsonErrors, BadPddlIsAnObjectWithFileLineAndColumn) {
    const std::string domain = data("bad/undefined-predicate.pddl");
    json error = stdout_json("plan --json " + domain + " " + data("bad/ok-problem.pddl"), 2);
    EXPECT_EQ(error, (json{{"status", "error"},
                           {"exit_code", 2},
                           {"error", "undefined predicate 'q' in action 'a'"},
                           {"file", domain},
                           {"line", 6},
                           {"column", 20}}));
}

TEST(JsonErrors, UsageErrorsAndMissingFilesToo) {
    json usage = stdout_json("design --json", 2);
    EXPECT_EQ(usage, (json{{"status", "error"}, {"exit_code", 2}, {"error", "spec is required"}}));
    json missing = stdout_json("design " + data("no-such-spec.textproto") + " --json", 2);
    EXPECT_EQ(missing["file"], data("no-such-spec.textproto"));
    EXPECT_FALSE(missing.contains("line")); // not known: the file is not there
    json url = stdout_json("design " + data("usability/probabilities-1.1.textproto") +
                               " --json --connect tcp://nowhere",
                           2);
    EXPECT_EQ(url["exit_code"], 2);
    EXPECT_NE(url["error"].get<std::string>().find("tcp://nowhere"), std::string::npos) << url;
}

TEST(JsonErrors, NoCoordinatorIsExitOneWithAnObject) {
    std::string url = testing::udpm_test_url(testing::claim_udp_port()); // no coordinator there
    json error = stdout_json("status --json --seconds 0.2 --connect '" + url + "'", 1);
    EXPECT_EQ(error["status"], "error");
    EXPECT_EQ(error["exit_code"], 1);
    EXPECT_NE(error["error"].get<std::string>().find("no coordinator on this bus"),
              std::string::npos);
}

struct JsonSpecError {
    std::string file;
    int line, column; // of the key at fault, counted by hand in the file
    std::string says;
};

void PrintTo(const JsonSpecError &e, std::ostream *out) { *out << e.file; }

class JsonSpecErrors : public ::testing::TestWithParam<JsonSpecError> {};

// protobuf's JSON parser gives no positions; these used to point to 1:1.
TEST_P(JsonSpecErrors, PointAtTheKey) {
    const JsonSpecError &e = GetParam();
    const std::string spec = data("usability/" + e.file);
    CommandResult text = run_envdesign("design " + spec);
    EXPECT_EQ(text.exit_code, 2);
    std::string where =
        spec + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": error: ";
    EXPECT_NE(text.out.find(where + e.says), std::string::npos) << text.out;
    json error = stdout_json("design " + spec + " --json", 2);
    EXPECT_EQ(error["line"], e.line);
    EXPECT_EQ(error["column"], e.column);
}

INSTANTIATE_TEST_SUITE_P(
    Positions, JsonSpecErrors,
    ::testing::Values(
        // line 5: `    {"name": "second", ..., "probability": "lots"}`, the key at column 49
        JsonSpecError{"bad-probability-type.json", 5, 49,
                      "task[1].probability: invalid value \"lots\""},
        // line 5: `    {"name": "paint", "cost": 1, "colour": "red",`
        JsonSpecError{"unknown-field.json", 5, 34, "unknown field 'modification[0].colour'"},
        // line 6: `     "edit": [{"model": "OBSERVERS", ...`, the key "model" at column 16
        JsonSpecError{"bad-enum.json", 6, 16,
                      "'OBSERVERS' is not a value of model: BOTH, ROBOT or HUMAN"},
        // two kinds in one edit: the second, "remove_init", at column 53
        JsonSpecError{"two-edit-kinds.json", 6, 53,
                      "only one field of 'kind' may be given: "
                      "'modification[0].edit[0].remove_init' is a second one"},
        // line 5: `  "beta": 2, "alpha": 3`, the second "alpha" at column 14
        JsonSpecError{"duplicate-key.json", 5, 14, "'alpha' is given twice"}));

TEST(Warnings, ProbabilitiesThatDoNotSumToOneSaySoAndHowTheyWereNormalised) {
    const std::string spec = data("usability/probabilities-1.1.textproto");
    json result = stdout_json("design " + spec + " --json", 0);
    // 0.6 + 0.5 = 1.1; 0.6 / 1.1 = 0.545454..., 0.5 / 1.1 = 0.454545... At 4:44, the first
    // task's "probability": `task { name: "first" problem: "has-a.pddl" ` is 43 characters.
    ASSERT_EQ(result["warnings"].size(), 1u) << result;
    EXPECT_EQ(result["warnings"][0], spec + ":4:44: warning: the task probabilities sum to 1.1, "
                                            "not 1; they were normalised to first 0.545455, "
                                            "second 0.454545");
    EXPECT_NEAR(result["tasks"][0]["probability"].get<double>(), 6.0 / 11, 1e-12);
    EXPECT_NEAR(result["tasks"][1]["probability"].get<double>(), 5.0 / 11, 1e-12);
    CommandResult text = run_envdesign("design " + spec);
    EXPECT_NE(text.out.find("warning: the task probabilities sum to 1.1"), std::string::npos);
    // Probabilities that sum to 1 (the restaurant's 0.5 + 0.5) give no warning.
    json quiet = stdout_json("design " + std::string(ENVDESIGN_TEST_DATA) +
                                 "/../../examples/restaurant/"
                                 "b-two-tasks-t1.textproto --json",
                             0);
    EXPECT_FALSE(quiet.contains("warnings")) << quiet["warnings"];
}

TEST(Warnings, TasksUnsolvableWithoutModificationsAreNamedWithTheReason) {
    const std::string spec = data("usability/unsolvable-tasks.textproto");
    // Every design's objective is infinite: exit 3 (friction_test.cc has its reason).
    json result = stdout_json("design " + spec + " --json", 3);
    EXPECT_EQ(result["objective"], "inf");
    EXPECT_EQ(result["warnings"],
              (json{"task 'robot-stuck' has infinite IE in the unmodified models: P_R has no "
                    "plan (the robot cannot do the task)",
                    "task 'human-stuck' has infinite IE in the unmodified models: P_H has no "
                    "plan (observers believe the task impossible)",
                    "task 'disagree' has infinite IE in the unmodified models: no plan is "
                    "valid in both P_R and P_H (P_mod has no plan)"}));
    CommandResult text = run_envdesign("design " + spec);
    EXPECT_TRUE(std::regex_search(text.out, std::regex("objective: \"?inf"))) << text.out;
    EXPECT_NE(text.out.find("warning: task 'disagree' has infinite IE"), std::string::npos);
}

// Ctrl-C in-process: the search stops as at a time limit and prints the best design so far
// (exit 4), as `--connect` does. 16 modifications, every subset: minutes of work.
TEST(Interrupt, CtrlCPrintsTheBestDesignSoFarWithExitFour) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("envdesign-sigint-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string spec =
        std::string(ENVDESIGN_TEST_DATA) + "/../e2e/data/warehouse/signs-1.textproto";
    Process design({"/bin/bash", "-c",
                    "exec " + std::string(ENVDESIGN_BIN_DIR) + "/envdesign design " + spec +
                        " --search exhaustive --max-design-size 0 --json > " +
                        (dir / "out").string() + " 2> " + (dir / "err").string()},
                   (dir / "log").string());
    std::this_thread::sleep_for(std::chrono::seconds(2)); // loaded, searching
    ASSERT_TRUE(design.running()) << "finished before Ctrl-C: the problem is too small";
    design.signal(SIGINT);
    auto code = design.wait(std::chrono::seconds(10));
    ASSERT_TRUE(code.has_value()) << "still running 10 s after Ctrl-C";
    EXPECT_EQ(*code, 4);
    std::ifstream out(dir / "out"), err(dir / "err");
    std::stringstream out_text, err_text;
    out_text << out.rdbuf();
    err_text << err.rdbuf();
    json result = json::parse(out_text.str(), nullptr, false);
    ASSERT_FALSE(result.is_discarded()) << out_text.str() << err_text.str();
    EXPECT_EQ(result["status"], "best_found");
    EXPECT_EQ(result["limit_reached"], true);
    EXPECT_TRUE(result["design"].is_array());
    EXPECT_TRUE(result["objective"].is_number()) << result["objective"];
    EXPECT_NE(err_text.str().find("interrupted; the design is the best found"), std::string::npos)
        << err_text.str();
    fs::remove_all(dir);
}

} // namespace
} // namespace envdesign::testing
