// Bad design problem files: the real binary exits 2 and names the spec file's line.

#include "../cli/run_command.h"

#include <gtest/gtest.h>

namespace envdesign::testing {
namespace {

struct BadSpec {
    std::string file;     // in data/design/bad
    std::string expected; // "FILE:LINE:..." prefix and message part
};

void PrintTo(const BadSpec &spec, std::ostream *out) { *out << spec.file; }

class BadSpecTest : public ::testing::TestWithParam<BadSpec> {};

TEST_P(BadSpecTest, ExitsTwoAndNamesTheLine) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/design/bad/";
    CommandResult result = run_envdesign("design " + dir + GetParam().file + " --json");
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_NE(result.out.find(dir + GetParam().expected), std::string::npos)
        << "expected '" << GetParam().expected << "' in:\n"
        << result.out;
}

INSTANTIATE_TEST_SUITE_P(
    Specs, BadSpecTest,
    ::testing::Values(
        BadSpec{"unknown-action.textproto",
                "unknown-action.textproto:6:43: error: unknown action 'fly'"},
        BadSpec{"arity.textproto",
                "arity.textproto:6:23: error: 'connected' takes 2 argument(s) but is given 1"},
        BadSpec{"unknown-object.textproto",
                "unknown-object.textproto:7:10: error: undefined object or constant 'c99'"},
        BadSpec{"unknown-parameter.textproto",
                "unknown-parameter.textproto:6:38: error: undefined variable '?somewhere'"},
        BadSpec{
            "remove-absent.textproto",
            "remove-absent.textproto:6:23: error: (connected c00 c01) is not in the initial state"},
        BadSpec{"negative-probability.textproto",
                "negative-probability.textproto:5:8: error: the probability of task 'g2' must be"},
        BadSpec{"missing-file.textproto",
                "missing-file.textproto:4:19: error: cannot open 'nowhere.pddl'"},
        BadSpec{"malformed.textproto", "malformed.textproto:8:1: error: Expected identifier"},
        BadSpec{"unknown-field.textproto",
                "unknown-field.textproto:4:1: error: unknown field 'alhpa' in the design "
                "problem (did you mean 'alpha'?)"},
        BadSpec{"no-kind.textproto", "no-kind.textproto:6:3: error: an edit needs exactly one of"},
        BadSpec{"two-kinds.textproto", "two-kinds.textproto:6:"},
        BadSpec{"unbalanced-literal.textproto", "unbalanced-literal.textproto:6:"},
        BadSpec{"no-task.textproto",
                "no-task.textproto:1:1: error: the design problem has no task"},
        BadSpec{"malformed.json", "malformed.json:4:"},
        BadSpec{"unknown-object.json",
                "unknown-object.json:7:16: error: undefined object or constant 'c99'"}));

TEST(BadSpec, AMissingSpecFileExitsTwo) {
    CommandResult result = run_envdesign("design /nonexistent/spec.textproto");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(
        result.out.find(
            "/nonexistent/spec.textproto: error: cannot open file: No such file or directory"),
        std::string::npos)
        << result.out;
}

// --connect with a URL that is not LCM's: a usage error naming it, not a 30 s wait.
TEST(BadSpec, ConnectToANonLcmUrlIsAUsageError) {
    CommandResult result = run_envdesign("design " + std::string(ENVDESIGN_EXAMPLES) +
                                         "/restaurant/a-one-task-t1.textproto --connect bogus://x");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.out.find("'bogus://x' is not an LCM URL"), std::string::npos) << result.out;
}

} // namespace
} // namespace envdesign::testing
