// What the reader makes of valid PDDL: the lifted structures, checked field by field.

#include "pddl/parser.h"

#include <gtest/gtest.h>

namespace envdesign::pddl {
namespace {

const std::string TINY = std::string(ENVDESIGN_TEST_DATA) + "/tiny/";

TEST(Parser, ReadsTypesConstantsAndEither) {
    Domain d = parse_domain_file(TINY + "domain.pddl");
    EXPECT_EQ(d.name, "tiny");
    EXPECT_EQ(d.type_parent.at("room"), "place");
    EXPECT_EQ(d.type_parent.at("corridor"), "place");
    EXPECT_EQ(d.type_parent.at("place"), "object"); // implicit parent
    EXPECT_EQ(d.type_parent.at("robot"), "object");
    ASSERT_EQ(d.constants.size(), 1u);
    EXPECT_EQ(d.constants[0].name, "hub");
    EXPECT_EQ(d.constants[0].types, std::vector<std::string>{"corridor"});
    const Action *move = d.find_action("move");
    ASSERT_NE(move, nullptr);
    ASSERT_EQ(move->parameters.size(), 3u);
    EXPECT_EQ(move->parameters[1].types, (std::vector<std::string>{"room", "corridor"}));
}

TEST(Parser, ReadsConditionsEffectsAndCosts) {
    Domain d = parse_domain_file(TINY + "domain.pddl");
    const Action *move = d.find_action("move");
    ASSERT_EQ(move->precondition.size(), 4u);
    EXPECT_EQ(move->precondition[2].to_string(), "(not (locked ?to))");
    EXPECT_EQ(move->precondition[3].to_string(), "(not (= ?from ?to))");
    ASSERT_EQ(move->effect.size(), 3u);
    EXPECT_TRUE(move->effect[0].negated);
    ASSERT_EQ(move->costs.size(), 1u);
    EXPECT_EQ(move->costs[0].function->to_string(), "(distance ?from ?to)");
    EXPECT_EQ(d.find_action("unlock")->costs[0].constant, 5);
}

TEST(Parser, ReadsProblemInitFunctionsGoalAndMetric) {
    Domain d = parse_domain_file(TINY + "domain.pddl");
    Problem p = parse_problem_file(TINY + "problem.pddl", d);
    EXPECT_EQ(p.objects.size(), 3u);
    EXPECT_EQ(p.init.size(), 8u);
    EXPECT_EQ(p.function_values.size(), 6u);
    EXPECT_EQ(p.function_values.at(Atom{"distance", {"kitchen", "lab"}, {}}), 1);
    ASSERT_EQ(p.goal.size(), 2u);
    EXPECT_EQ(p.goal[1].to_string(), "(visited hub)");
    EXPECT_TRUE(p.minimize_total_cost);
}

TEST(Parser, IsCaseInsensitiveAndSkipsComments) {
    SExpr e = read_sexpr("(Define ; a comment (\n (DOMAIN Mixed))", "mem");
    EXPECT_EQ(e.to_string(), "(define (domain mixed))");
}

TEST(Parser, RejectsAnInitAtomListedTrueAndFalseWithItsLocation) {
    Domain d =
        parse_domain(read_sexpr("(define (domain d) (:predicates (p ?x)))", "d.pddl"), "d.pddl");
    try {
        parse_problem(read_sexpr("(define (problem q) (:domain d) (:objects a)\n"
                                 "  (:init (p a) (not (p a))) (:goal (p a)))",
                                 "q.pddl"),
                      "q.pddl", d);
        FAIL() << "expected a ParseError";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.location().line, 2);
        EXPECT_EQ(e.location().column, 16);
        EXPECT_NE(std::string(e.what()).find("(p a) is listed as both true and false"),
                  std::string::npos);
    }
}

} // namespace
} // namespace envdesign::pddl
