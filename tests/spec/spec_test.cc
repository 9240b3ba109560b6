// Reading design problem files: text format and JSON give the same problem; fields are
// located for messages.

#include "spec/design_spec.h"
#include "spec/spec_reader.h"

#include <gtest/gtest.h>

namespace envdesign::spec {
namespace {

using design::DesignProblem;
using design::Distance;
using design::Model;

const std::string EXAMPLES = std::string(ENVDESIGN_EXAMPLES) + "/restaurant/";
const std::string DATA = std::string(ENVDESIGN_TEST_DATA) + "/design/";

TEST(Spec, TextAndJsonGiveTheSameProblem) {
    DesignProblem text = load_design_problem(EXAMPLES + "c-two-tasks-t10.textproto");
    DesignProblem json = load_design_problem(DATA + "restaurant-c.json");
    ASSERT_EQ(text.tasks.size(), 2u);
    ASSERT_EQ(json.tasks.size(), 2u);
    for (std::size_t t = 0; t < 2; ++t) {
        EXPECT_EQ(text.tasks[t].name, json.tasks[t].name);
        EXPECT_DOUBLE_EQ(text.tasks[t].probability, json.tasks[t].probability);
        EXPECT_EQ(text.tasks[t].human_problem.init.size(), json.tasks[t].human_problem.init.size());
    }
    ASSERT_EQ(text.modifications.size(), 6u);
    ASSERT_EQ(json.modifications.size(), 6u);
    for (std::size_t m = 0; m < 6; ++m) {
        EXPECT_EQ(text.modifications[m].name, json.modifications[m].name);
        ASSERT_EQ(json.modifications[m].edits.size(), 2u);
        EXPECT_EQ(text.modifications[m].edits[1].expression.to_string(),
                  json.modifications[m].edits[1].expression.to_string());
        EXPECT_EQ(json.modifications[m].edits[1].model, Model::HUMAN);
    }
    EXPECT_DOUBLE_EQ(json.weights.beta, 30);
    EXPECT_DOUBLE_EQ(json.weights.gamma, 0.9);
    EXPECT_EQ(json.weights.horizon, 10);
}

TEST(Spec, DefaultsWhenFieldsAreAbsent) {
    SpecFile spec =
        read_spec_text("robot_domain: \"domain.pddl\"\n"
                       "task { name: \"a\" problem: \"serve-g1.pddl\" }\n"
                       "task { name: \"b\" problem: \"serve-g2.pddl\" probability: 3 }\n",
                       EXAMPLES + "inline.textproto");
    DesignProblem p = load_design_problem(spec);
    EXPECT_DOUBLE_EQ(p.tasks[0].probability, 0.25); // absent = 1, normalised over 1 + 3
    EXPECT_DOUBLE_EQ(p.tasks[1].probability, 0.75);
    EXPECT_DOUBLE_EQ(p.weights.alpha, 1);
    EXPECT_DOUBLE_EQ(p.weights.gamma, 1);
    EXPECT_EQ(p.weights.horizon, 1);
    EXPECT_EQ(p.weights.distance, Distance::EXP_COST_DIFF);
    EXPECT_EQ(p.tasks[0].human_problem.init.size(), p.tasks[0].robot_problem.init.size());
}

TEST(Spec, FieldsAreLocatedInTextAndJson) {
    SpecFile text = read_spec_file(EXAMPLES + "c-two-tasks-t10.textproto");
    EXPECT_EQ(text.at("task[1]").line, 6);
    EXPECT_EQ(text.at("modification[1].edit[1].remove_init").line, 15);
    EXPECT_EQ(text.at("horizon").line, 37);
    SpecFile json = read_spec_file(DATA + "restaurant-c.json");
    EXPECT_EQ(json.at("task[1].human_problem").line, 13);
    EXPECT_EQ(json.at("task[0].human_problem").line, 7); // written "humanProblem"
}

TEST(Spec, ErrorsNameTheLineOfTheEdit) {
    try {
        load_design_problem(DATA + "bad/unknown-object.textproto");
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        EXPECT_EQ(e.location().line, 7);
        EXPECT_NE(e.message().find("undefined object or constant 'c99'"), std::string::npos)
            << e.what();
        EXPECT_NE(e.message().find("human model of task 'g1'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace envdesign::spec
