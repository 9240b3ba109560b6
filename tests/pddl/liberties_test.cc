// Liberties that Fast Downward's translator accepts (issue 12): each minimal file under
// tests/data/liberties names the real domain that needs it, or says that none of the IPC
// collection does.

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

TEST(Liberties, DeclarationsInAnyOrder) {
    Domain d = parse_domain_file(DATA + "sections-any-order-domain.pddl");
    EXPECT_EQ(d.type_parent.at("robot"), "object");
    ASSERT_EQ(d.predicates.size(), 2u);
    EXPECT_EQ(d.predicates[0].parameters[0].types, std::vector<std::string>{"robot"});
    EXPECT_EQ(d.requirements.count(":typing"), 1u);
}

TEST(Liberties, RequirementsBeyondTheFragmentAreDeclarationsOnly) {
    Domain d = parse_domain_file(DATA + "beyond-requirements-domain.pddl");
    ASSERT_EQ(d.actions.size(), 1u);
    EXPECT_EQ(d.actions[0].costs.size(), 1u);
    EXPECT_EQ(d.requirements.count(":adl"), 0u); // nothing of :adl is taken on
}

TEST(Liberties, InitAtomsListedFalseAreLeftOutAndARepeatedValueIsKept) {
    Domain d = parse_domain_file(DATA + "init-listed-false-domain.pddl");
    Problem p = parse_problem_file(DATA + "init-listed-false-problem.pddl", d);
    ASSERT_EQ(p.init.size(), 1u);
    EXPECT_EQ(p.init[0].to_string(), "(on l1)");
    EXPECT_EQ(p.function_values.size(), 3u);
    EXPECT_EQ(p.function_values.at(Atom{"switch-cost", {"l2"}, {}}), 3);
}

TEST(Liberties, ConflictingValuesAreRefusedWhereTheSecondIs) {
    Domain d = parse_domain_file(DATA + "init-listed-false-domain.pddl");
    try {
        parse_problem(read_sexpr("(define (problem q) (:domain init-listed-false) (:objects l1)\n"
                                 "  (:init (= (switch-cost l1) 4) (= (switch-cost l1) 5))\n"
                                 "  (:goal (on l1)))",
                                 "q.pddl"),
                      "q.pddl", d);
        FAIL() << "expected a ParseError";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.location().line, 2);
        EXPECT_EQ(e.location().column, 33);
        EXPECT_NE(std::string(e.what()).find("conflicting values 4 and 5 for (switch-cost l1)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Liberties, DoubleNegationIsTheLiteral) {
    Domain d = parse_domain_file(DATA + "double-negation-domain.pddl");
    const Action *finish = d.find_action("finish");
    ASSERT_NE(finish, nullptr);
    ASSERT_EQ(finish->precondition.size(), 2u);
    EXPECT_EQ(finish->precondition[0].to_string(), "(ready ?x)");
    EXPECT_EQ(finish->precondition[1].to_string(), "(not (done ?x))");
    Problem p = parse_problem_file(DATA + "double-negation-problem.pddl", d);
    ASSERT_EQ(p.goal.size(), 2u);
    EXPECT_EQ(p.goal[1].to_string(), "(done j2)");
}

} // namespace
} // namespace envdesign::pddl
