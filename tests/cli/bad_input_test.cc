// Every class of bad PDDL input gives exit code 2 and a FILE:LINE:COL message naming it.

#include "run_command.h"

#include <gtest/gtest.h>

namespace envdesign::testing {
namespace {

struct BadInput {
    std::string domain;
    std::string problem;
    std::string expected; // "FILE:LINE:COL: error: ..." prefix, FILE relative to data/bad
};

void PrintTo(const BadInput &b, std::ostream *out) { *out << b.domain << " " << b.problem; }

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ExitsTwoAndNamesThePlace) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/bad/";
    const BadInput &input = GetParam();
    CommandResult result = run_envdesign("plan " + dir + input.domain + " " + dir + input.problem);
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_NE(result.out.find(dir + input.expected), std::string::npos)
        << "expected '" << input.expected << "' in:\n"
        << result.out;
}

INSTANTIATE_TEST_SUITE_P(
    PddlErrors, BadInputTest,
    ::testing::Values(
        BadInput{"unbalanced.pddl", "ok-problem.pddl",
                 "unbalanced.pddl:1:1: error: unbalanced parentheses"},
        BadInput{"ok-domain.pddl", "extra-paren-problem.pddl",
                 "extra-paren-problem.pddl:5:3: error: unexpected text after the closing"},
        BadInput{"undefined-predicate.pddl", "ok-problem.pddl",
                 "undefined-predicate.pddl:6:20: error: undefined predicate 'q' in action 'a'"},
        BadInput{"undefined-type.pddl", "ok-problem.pddl",
                 "undefined-type.pddl:4:24: error: undefined type 'blok'"},
        BadInput{"undefined-constant.pddl", "ok-problem.pddl",
                 "undefined-constant.pddl:7:34: error: undefined object or constant 'table'"},
        BadInput{"ok-domain.pddl", "undefined-object-problem.pddl",
                 "undefined-object-problem.pddl:5:18: error: undefined object or constant 'o3'"},
        BadInput{"arity.pddl", "ok-problem.pddl",
                 "arity.pddl:6:19: error: 'p' takes 1 argument(s) but is given 2"},
        BadInput{"unknown-requirement.pddl", "ok-problem.pddl",
                 "unknown-requirement.pddl:2:26: error: unknown requirement ':teleportation'"},
        BadInput{"duplicate-predicate.pddl", "ok-problem.pddl",
                 "duplicate-predicate.pddl:4:16: error: predicate 'p' is declared twice with "
                 "different parameters"},
        BadInput{"ok-domain.pddl", "duplicate-object-problem.pddl",
                 "duplicate-object-problem.pddl:4:13: error: duplicate object 'o1'"},
        BadInput{"unsupported-forall.pddl", "ok-problem.pddl",
                 "unsupported-forall.pddl:6:19: error: 'forall' (universal quantification) "
                 "is not supported"},
        // a requirement beyond the fragment is accepted; the construct is refused where used
        BadInput{"beyond-requirement-used.pddl", "ok-problem.pddl",
                 "beyond-requirement-used.pddl:7:13: error: 'when' (conditional effects) is not "
                 "supported"},
        BadInput{"not-over-and.pddl", "ok-problem.pddl",
                 "not-over-and.pddl:6:24: error: 'not' over 'and' (a disjunction) is not "
                 "supported"},
        BadInput{"ok-domain.pddl", "timed-literal-problem.pddl",
                 "timed-literal-problem.pddl:4:17: error: a timed initial literal"},
        BadInput{"ok-domain.pddl", "preference-problem.pddl",
                 "preference-problem.pddl:5:28: error: 'preference' (preferences) is not "
                 "supported"},
        BadInput{"ok-domain.pddl", "init-true-and-false-problem.pddl",
                 "init-true-and-false-problem.pddl:5:10: error: (p o1) is listed as both true "
                 "and false"},
        BadInput{"byte-order-mark.pddl", "ok-problem.pddl",
                 "byte-order-mark.pddl:1:1: error: the file starts with a UTF-8 byte-order mark"},
        BadInput{"double-negation-effect.pddl", "ok-problem.pddl",
                 "double-negation-effect.pddl:7:18: error: 'not' inside 'not' is allowed in a "
                 "condition, not here"},
        BadInput{"unsupported-requirement.pddl", "ok-problem.pddl",
                 "unsupported-requirement.pddl:2:26: error: requirement ':durative-actions' is "
                 "not supported"},
        BadInput{"missing.pddl", "ok-problem.pddl",
                 "missing.pddl: error: cannot open file: No such file or directory"}));

TEST(BadFlags, UnknownHeuristicIsAUsageError) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/bad/";
    CommandResult result =
        run_envdesign("plan " + dir + "ok-domain.pddl " + dir + "ok-problem.pddl --heuristic ff");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.out.find("--heuristic"), std::string::npos) << result.out;
}

TEST(BadFlags, MissingProblemIsAUsageError) {
    CommandResult result = run_envdesign("plan only-one-file.pddl");
    EXPECT_EQ(result.exit_code, 2);
}

} // namespace
} // namespace envdesign::testing
