// What a new user met (issue 25) and now gets, through the real binary: a ranking without
// padded designs (item 4), and errors that say what is wrong and where (item 5): the nearest
// field name, the values of an enum, the place of a missing ')', an output path checked before
// the search, exit 3 for an infinite best objective, a warning when a task's two problems
// disagree on the goal, a missing file named without a line.

#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

namespace envdesign::testing {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string example(const std::string &name) {
    return std::string(ENVDESIGN_EXAMPLES) + "/restaurant/" + name;
}

// A scratch folder with the restaurant's files and `spec` written as spec.textproto.
std::string restaurant_with(const std::string &name, const std::string &spec) {
    fs::path dir = fs::path(::testing::TempDir()) / ("friction-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const char *file : {"domain.pddl", "serve-g1.pddl", "serve-g1-human.pddl", "serve-g2.pddl",
                             "serve-g2-human.pddl"})
        fs::copy_file(example(file), dir / file);
    std::ofstream(dir / "spec.textproto") << spec;
    return dir.string();
}

std::string read(const std::string &path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The restaurant's setting (c) with `from` replaced by `to` once.
std::string setting_c_with(const std::string &from, const std::string &to) {
    std::string spec = read(example("c-two-tasks-t10.textproto"));
    auto at = spec.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return spec.replace(at, from.size(), to);
}

json ranking_of(const std::string &arguments) {
    CommandResult r = run_envdesign(arguments + " --json", false);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return json::parse(r.out, nullptr, false);
}

std::vector<std::vector<std::string>> designs(const json &result) {
    std::vector<std::vector<std::string>> out;
    for (const auto &point : result["ranking"])
        out.push_back(point["design"].get<std::vector<std::string>>());
    return out;
}

bool has_note(const json &result, const std::string &words) {
    for (const auto &note : result["notes"])
        if (note.get<std::string>().find(words) != std::string::npos)
            return true;
    return false;
}

// padded.textproto: setting (c) and paint-wall, a modification of cost 0 that changes no plan.
// The two best designs tie at 85.26; with paint-wall they tie again (more modifications rank
// later), then come the single barriers at 96.88.
TEST(Ranking, LeavesOutDesignsPaddedWithAModificationThatDoesNotPay) {
    const std::string spec = data("ranking/padded.textproto");
    using D = std::vector<std::vector<std::string>>;
    json all = ranking_of("design " + spec + " --ranking 4 --ranking-all");
    EXPECT_EQ(designs(all), (D{{"barrier-00-01", "barrier-10-11"},
                               {"barrier-01-02", "barrier-11-12"},
                               {"barrier-00-01", "barrier-10-11", "paint-wall"},
                               {"barrier-01-02", "barrier-11-12", "paint-wall"}}))
        << all["ranking"];
    EXPECT_FALSE(has_note(all, "--ranking-all")) << all["notes"];
    const D paying{{"barrier-00-01", "barrier-10-11"},
                   {"barrier-01-02", "barrier-11-12"},
                   {"barrier-00-01"},
                   {"barrier-01-02"}};
    for (const char *search : {"witness", "exhaustive"}) {
        json shown = ranking_of("design " + spec + " --ranking 4 --search " + search);
        EXPECT_EQ(designs(shown), paying) << search << ": " << shown["ranking"];
        EXPECT_NEAR(shown["ranking"][2]["objective"].get<double>(), 96.88, 0.01);
        EXPECT_TRUE(has_note(shown, "every modification pays for itself")) << shown["notes"];
    }
    // In text too: the note says what was left out and how to see it.
    CommandResult text = run_envdesign("design " + spec + " --ranking 4", false);
    EXPECT_NE(text.out.find("  3. 96.88  {barrier-00-01}\n"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("were left out (--ranking-all lists them)"), std::string::npos);
}

TEST(Errors, AMisspelledFieldGetsTheNearestName) {
    std::string dir =
        restaurant_with("field", setting_c_with("probability: 0.5 }", "probabilty: 0.5 }"));
    CommandResult r = run_envdesign("design " + dir + "/spec.textproto");
    EXPECT_EQ(r.exit_code, 2);
    // Line 5 is the first task; `probabilty` starts at column 87, where the error points.
    EXPECT_NE(r.out.find(dir + "/spec.textproto:5:87: error: unknown field 'probabilty' in task "
                               "(did you mean 'probability'?)"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("Message type"), std::string::npos) << r.out; // not protobuf's words
    // Nothing near: the fields there are.
    dir = restaurant_with("far", setting_c_with("alpha: 1", "colour: 1"));
    r = run_envdesign("design " + dir + "/spec.textproto");
    EXPECT_NE(r.out.find("unknown field 'colour' in the design problem; its fields are "
                         "robot_domain, human_domain, task,"),
              std::string::npos)
        << r.out;
}

TEST(Errors, ABadEnumValueListsTheValues) {
    std::string dir = restaurant_with("enum", setting_c_with("model: HUMAN", "model: HUMANS"));
    CommandResult r = run_envdesign("design " + dir + "/spec.textproto");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.out.find(dir + "/spec.textproto:9:17: error: 'HUMANS' is not a value of model: "
                               "BOTH, ROBOT or HUMAN (did you mean HUMAN?)"),
              std::string::npos)
        << r.out;
}

TEST(Errors, AMissingParenthesisIsReportedWhereItIsMissing) {
    std::string domain = read(example("domain.pddl"));
    // The predicates' list left open: the next section shows where it should have closed.
    std::string dir = restaurant_with("paren-section", "");
    std::string open_section =
        std::regex_replace(domain, std::regex(R"(\(hand-empty\)\))"), "(hand-empty)",
                           std::regex_constants::format_first_only);
    std::ofstream(dir + "/domain.pddl") << open_section;
    CommandResult r = run_envdesign("plan " + dir + "/domain.pddl " + dir + "/serve-g1.pddl");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.out.find(dir + "/domain.pddl:12:3: error: missing ')' before this section: "
                               "'(:predicates' (opened at line 7) is still open"),
              std::string::npos)
        << r.out;
    // A precondition left open: the next line is indented no deeper than its own.
    std::string open_and =
        std::regex_replace(domain, std::regex(R"(\(connected \?from \?to\)\))"),
                           "(connected ?from ?to)", std::regex_constants::format_first_only);
    std::ofstream(dir + "/domain.pddl") << open_and;
    r = run_envdesign("plan " + dir + "/domain.pddl " + dir + "/serve-g1.pddl");
    EXPECT_NE(r.out.find(dir + "/domain.pddl:15:5: error: missing ')' before this line: '(and' "
                               "(opened at line 14) is still open"),
              std::string::npos)
        << r.out;
    // The last ')' missing: nothing else is out of place, so the '(' never closed is named.
    std::string last = domain.substr(0, domain.find_last_of(')'));
    std::ofstream(dir + "/domain.pddl") << last;
    r = run_envdesign("plan " + dir + "/domain.pddl " + dir + "/serve-g1.pddl");
    EXPECT_NE(r.out.find(dir + "/domain.pddl:4:1: error: unbalanced parentheses: this '(' is "
                               "never closed"),
              std::string::npos)
        << r.out;
}

TEST(Errors, AReportIntoAMissingFolderFailsBeforeTheSearch) {
    const std::string out = ::testing::TempDir() + "/no-such-folder/report.html";
    CommandResult r =
        run_envdesign("report " + example("c-two-tasks-t10.textproto") + " -o " + out);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find("cannot write '" + out + "': " + ::testing::TempDir() +
                         "/no-such-folder: No such file or directory"),
              std::string::npos)
        << r.out;
    // Before the search: it prints no summary of one.
    EXPECT_EQ(r.out.find("configurations"), std::string::npos) << r.out;
    // A folder as the output: the OS's words for it.
    r = run_envdesign("report " + example("c-two-tasks-t10.textproto") + " -o " +
                      ::testing::TempDir());
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find(": Is a directory"), std::string::npos) << r.out;
}

TEST(Errors, AnInfiniteBestObjectiveExitsThreeWithTheReason) {
    const std::string spec = data("usability/unsolvable-tasks.textproto");
    CommandResult r = run_envdesign("design " + spec + " --json", false);
    EXPECT_EQ(r.exit_code, 3);
    json result = json::parse(r.out, nullptr, false);
    EXPECT_EQ(result["status"], "unsolvable");
    EXPECT_EQ(result["reason"], "every design has an infinite objective: no design gives task(s) "
                                "'robot-stuck', 'human-stuck', 'disagree' a finite IE");
    EXPECT_EQ(result["objective"], "inf");
    CommandResult text = run_envdesign("design " + spec, false);
    EXPECT_EQ(text.exit_code, 3);
    EXPECT_EQ(text.out.rfind("status: unsolvable (every design has an infinite objective", 0), 0u)
        << text.out;
    // A finite best objective is still 0 and optimal.
    CommandResult fine = run_envdesign("design " + example("a-one-task-t1.textproto"), false);
    EXPECT_EQ(fine.exit_code, 0);
    EXPECT_EQ(fine.out.rfind("status: optimal\n", 0), 0u) << fine.out;
}

TEST(Warnings, TheTwoProblemsOfATaskDisagreeOnTheGoal) {
    std::string dir = restaurant_with("goal", read(example("c-two-tasks-t10.textproto")));
    std::string robot = read(dir + "/serve-g1.pddl");
    std::smatch goal;
    ASSERT_TRUE(std::regex_search(robot, goal, std::regex(R"(\(:goal[^\n]*)")));
    std::ofstream(dir + "/serve-g1.pddl")
        << robot.replace(goal.position(0), goal.length(0), "(:goal (and)))");
    CommandResult r = run_envdesign("design " + dir + "/spec.textproto --json", false);
    json result = json::parse(r.out, nullptr, false);
    ASSERT_TRUE(result.contains("warnings")) << r.out;
    ASSERT_EQ(result["warnings"].size(), 1u) << result["warnings"];
    std::string warning = result["warnings"][0];
    EXPECT_EQ(warning.rfind(dir + "/spec.textproto:5:50: warning: ", 0), 0u) << warning;
    EXPECT_NE(warning.find("warning: the two problems of task 'serve-g1' have different goals: "
                           "(and) in the robot's (serve-g1.pddl), (and (item-at dish "),
              std::string::npos)
        << warning;
    // The other task's goals agree: no word of it.
    EXPECT_EQ(warning.find("serve-g2"), std::string::npos) << warning;
    CommandResult quiet =
        run_envdesign("design " + example("c-two-tasks-t10.textproto") + " --json", false);
    EXPECT_FALSE(json::parse(quiet.out, nullptr, false).contains("warnings")) << quiet.out;
}

TEST(Errors, AMissingSpecFileIsNamedWithoutALine) {
    CommandResult r = run_envdesign("design flor.textproto");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "flor.textproto: error: cannot open file: No such file or directory\n");
    json error = json::parse(run_envdesign("design flor.textproto --json", false).out);
    EXPECT_EQ(error, (json{{"status", "error"},
                           {"exit_code", 2},
                           {"error", "cannot open file: No such file or directory"},
                           {"file", "flor.textproto"}}));
}

} // namespace
} // namespace envdesign::testing
