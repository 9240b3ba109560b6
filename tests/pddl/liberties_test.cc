// Liberties that real IPC domains take and Fast Downward's translator accepts (issue 12):
// each minimal file under tests/data/liberties names the domain that needs it.

#include "pddl/parser.h"

#include <gtest/gtest.h>

namespace envdesign::pddl {
namespace {

const std::string DATA = std::string(ENVDESIGN_TEST_DATA) + "/liberties/";

TEST(Liberties, TypeListedTwiceTakesTheMoreSpecificParent) {
    Domain d = parse_domain_file(DATA + "type-listed-twice-domain.pddl");
    EXPECT_EQ(d.type_parent.at("area"), "surface");
    EXPECT_EQ(d.type_parent.at("crate"), "surface");
    EXPECT_EQ(d.type_parent.at("surface"), "object");
    Problem p = parse_problem_file(DATA + "type-listed-twice-problem.pddl", d);
    EXPECT_EQ(p.objects.size(), 6u);
}

TEST(Liberties, TypeUnderUnrelatedParentsIsRefusedWhereItIs) {
    try {
        parse_domain(read_sexpr("(define (domain d) (:types a b - object\n"
                                "  c - a c - b))",
                                "d.pddl"),
                     "d.pddl");
        FAIL() << "expected a ParseError";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.location().line, 2);
        EXPECT_NE(std::string(e.what()).find("unrelated parents"), std::string::npos) << e.what();
    }
}

TEST(Liberties, QuestionMarkStartsAVariableEvenWithoutSpace) {
    Domain d = parse_domain_file(DATA + "variable-glued-domain.pddl");
    const Action *fly = d.find_action("fly");
    ASSERT_NE(fly, nullptr);
    ASSERT_EQ(fly->precondition.size(), 4u);
    EXPECT_EQ(fly->precondition[0].to_string(), "(aircraft ?a)");
    EXPECT_EQ(fly->precondition[1].to_string(), "(city ?from)");
    EXPECT_EQ(fly->precondition[3].to_string(), "(at ?a ?from)");
    EXPECT_EQ(read_sexpr("(p ?x?y)", "mem").to_string(), "(p ?x ?y)");
}

} // namespace
} // namespace envdesign::pddl
