// Every edit kind on a small hand-written model, its errors, and STRICT vs LENIENT.

#include "design/model/edits.h"
#include "ground/grounder.h"
#include "pddl/parser.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace envdesign::design {
namespace {

const char *DOMAIN = R"((define (domain d) (:requirements :strips :typing)
  (:types cell)
  (:predicates (at ?c - cell) (connected ?a ?b - cell) (open ?c - cell))
  (:action move :parameters (?from ?to - cell)
    :precondition (and (at ?from) (connected ?from ?to))
    :effect (and (at ?to) (not (at ?from))))))";

const char *PROBLEM = R"((define (problem p) (:domain d) (:objects a b c - cell)
  (:init (at a) (connected a b) (connected b c) (connected a c))
  (:goal (at c))))";

const pddl::Location WHERE{"spec.textproto", 7, 3};

class EditsTest : public ::testing::Test {
protected:
    void SetUp() override {
        domain = pddl::parse_domain(pddl::read_sexpr(DOMAIN, "d.pddl"), "d.pddl");
        problem = pddl::parse_problem(pddl::read_sexpr(PROBLEM, "p.pddl"), "p.pddl", domain);
    }
    void apply(EditKind kind, const std::string &text, const std::string &action = "",
               ApplyMode mode = ApplyMode::STRICT) {
        apply_edit(parse_edit_text(kind, Model::BOTH, action, text, WHERE), domain, &problem, mode);
    }
    std::vector<std::string> init() const {
        std::vector<std::string> out;
        for (const auto &a : problem.init)
            out.push_back(a.to_string());
        return out;
    }
    static std::vector<std::string> strings(const std::vector<pddl::Literal> &literals) {
        std::vector<std::string> out;
        for (const auto &l : literals)
            out.push_back(l.to_string());
        return out;
    }
    std::string error_of(EditKind kind, const std::string &text, const std::string &action = "") {
        try {
            apply(kind, text, action);
        } catch (const pddl::ParseError &e) {
            EXPECT_EQ(e.location().to_string(), "spec.textproto:7:3");
            return e.message();
        }
        return "no error";
    }
    pddl::Domain domain;
    pddl::Problem problem;
};

TEST_F(EditsTest, AddAndRemoveInit) {
    apply(EditKind::ADD_INIT, "(open b)");
    apply(EditKind::ADD_INIT, "(OPEN b)", "", ApplyMode::LENIENT); // already there
    apply(EditKind::REMOVE_INIT, "(connected a b)");
    EXPECT_EQ(init(), (std::vector<std::string>{"(at a)", "(connected b c)", "(connected a c)",
                                                "(open b)"}));
    EXPECT_THROW(apply(EditKind::REMOVE_INIT, "(connected a b)"), NotPresentError);
    EXPECT_NO_THROW(apply(EditKind::REMOVE_INIT, "(connected a b)", "", ApplyMode::LENIENT));
}

TEST_F(EditsTest, AddAndRemoveGoal) {
    apply(EditKind::ADD_GOAL, "(not (open a))");
    apply(EditKind::REMOVE_GOAL, "(at c)");
    EXPECT_EQ(strings(problem.goal), (std::vector<std::string>{"(not (open a))"}));
    EXPECT_THROW(apply(EditKind::REMOVE_GOAL, "(at b)"), NotPresentError);
}

TEST_F(EditsTest, AddPredicateThenUseIt) {
    apply(EditKind::ADD_PREDICATE, "(visited ?c - cell)");
    apply(EditKind::ADD_EFFECT, "(visited ?to)", "move");
    ASSERT_NE(domain.find_predicate("visited"), nullptr);
    EXPECT_EQ(domain.find_predicate("visited")->parameters.at(0).types,
              std::vector<std::string>{"cell"});
    EXPECT_EQ(strings(domain.actions[0].effect),
              (std::vector<std::string>{"(at ?to)", "(not (at ?from))", "(visited ?to)"}));
    EXPECT_NE(error_of(EditKind::ADD_PREDICATE, "(visited ?c - cell)").find("already declared"),
              std::string::npos);
    EXPECT_NE(error_of(EditKind::ADD_PREDICATE, "(seen ?c - room)").find("undefined type 'room'"),
              std::string::npos);
}

TEST_F(EditsTest, PreconditionsAndEffects) {
    apply(EditKind::ADD_PRECONDITION, "(not (open ?to))", "move");
    apply(EditKind::REMOVE_PRECONDITION, "(connected ?from ?to)", "move");
    apply(EditKind::REMOVE_EFFECT, "(not (at ?from))", "move");
    EXPECT_EQ(strings(domain.actions[0].precondition),
              (std::vector<std::string>{"(at ?from)", "(not (open ?to))"}));
    EXPECT_EQ(strings(domain.actions[0].effect), (std::vector<std::string>{"(at ?to)"}));
    EXPECT_TRUE(domain.requirements.count(":negative-preconditions"));
    EXPECT_THROW(apply(EditKind::REMOVE_EFFECT, "(open ?to)", "move"), NotPresentError);
}

TEST_F(EditsTest, RemoveASchema) {
    apply(EditKind::REMOVE_ACTION, "move");
    EXPECT_TRUE(domain.actions.empty());
    EXPECT_NE(error_of(EditKind::REMOVE_ACTION, "move").find("unknown action 'move'"),
              std::string::npos);
}

TEST_F(EditsTest, RemoveOneGroundAction) {
    apply(EditKind::REMOVE_ACTION, "(move a c)");
    std::vector<std::string> names;
    for (const auto &op : ground::ground(domain, problem).operators)
        names.push_back(op.name);
    EXPECT_EQ(std::count(names.begin(), names.end(), "(move a c)"), 0);
    EXPECT_EQ(std::count(names.begin(), names.end(), "(move a b)"), 1);
    EXPECT_EQ(std::count(names.begin(), names.end(), "(move b c)"), 1);
}

TEST_F(EditsTest, BadNamesAreErrorsAtTheEdit) {
    EXPECT_NE(
        error_of(EditKind::ADD_PRECONDITION, "(open ?to)", "fly").find("unknown action 'fly'"),
        std::string::npos);
    EXPECT_NE(
        error_of(EditKind::ADD_INIT, "(connected a)").find("takes 2 argument(s) but is given 1"),
        std::string::npos);
    EXPECT_NE(error_of(EditKind::ADD_INIT, "(open z)").find("undefined object or constant 'z'"),
              std::string::npos);
    EXPECT_NE(error_of(EditKind::ADD_INIT, "(closed a)").find("undefined predicate 'closed'"),
              std::string::npos);
    EXPECT_NE(
        error_of(EditKind::ADD_PRECONDITION, "(open ?x)", "move").find("undefined variable '?x'"),
        std::string::npos);
    EXPECT_NE(error_of(EditKind::ADD_INIT, "(open ?x)").find("undefined variable '?x'"),
              std::string::npos);
    EXPECT_NE(error_of(EditKind::REMOVE_ACTION, "(move a)").find("takes 2 argument(s)"),
              std::string::npos);
}

TEST_F(EditsTest, MalformedTextIsAnErrorAtTheEdit) {
    try {
        parse_edit_text(EditKind::ADD_INIT, Model::BOTH, "", "(open a", WHERE);
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        EXPECT_EQ(e.location().to_string(), "spec.textproto:7:3");
        EXPECT_NE(e.message().find("unbalanced"), std::string::npos) << e.message();
    }
}

} // namespace
} // namespace envdesign::design
