// The one result formatter (clients/cpp/src/result_format.h) on the message both paths share:
// the explained result survives LCM encoding byte for byte, text numbers are rounded for
// reading, and the plan diff marks what differs.

#include "bus/codec.h"
#include "design/design_explanation.h"
#include "design/evaluation/local_evaluator.h"
#include "plan_diff.h"
#include "result_format.h"
#include "spec/design_spec.h"
#include "wire/result_message.h"

#include <gtest/gtest.h>

namespace envdesign::cluster {
namespace {

envdesign::design_result_t explained_restaurant() {
    design::DesignProblem problem = spec::load_design_problem(
        std::string(ENVDESIGN_TEST_DATA_ROOT) + "/examples/restaurant/c-two-tasks-t10.textproto");
    design::LocalEvaluator local(problem, 1);
    design::EvaluationLog log(problem, local);
    design::RunSettings settings;
    settings.time_limit_s = 0;
    settings.max_design_size = 0; // every size, as the message's reference
    settings.ranking = 3;
    return wire::result_message(problem,
                                design::run_design(problem, log, &local.planner(), settings));
}

// What --connect prints is what the local run prints: the explanation and the ranking
// travel in design_result_t and format to the same JSON after decoding.
TEST(ResultFormat, ExplanationSurvivesTheWire) {
    envdesign::design_result_t sent = explained_restaurant();
    ASSERT_TRUE(sent.has_explanation);
    envdesign::design_result_t received;
    ASSERT_TRUE(bus::decode_message(bus::encode_message(sent), received));
    EXPECT_EQ(client::result_json(received), client::result_json(sent));
    EXPECT_EQ(client::result_text(received), client::result_text(sent));
    nlohmann::json j = client::result_json_value(received);
    ASSERT_EQ(j.at("ranking").size(), 3u);
    EXPECT_EQ(j.at("ranking")[1].at("design"), nlohmann::json({"barrier-01-02", "barrier-11-12"}));
    EXPECT_EQ(j.at("explanation").at("tasks")[0].at("robot_optimal_cost"), 7);
}

// Warnings travel in the result, bounded: 1500 lines of 3000 bytes (a warning may quote a
// goal) become 1000 lines of at most 1 KiB and a count of the rest, so that a result stays
// far below the bus's largest message; short lines go as they are.
TEST(ResultFormat, WarningsTravelBounded) {
    design::DesignProblem problem = spec::load_design_problem(
        std::string(ENVDESIGN_TEST_DATA_ROOT) + "/examples/restaurant/c-two-tasks-t10.textproto");
    design::DesignRun run;
    run.warnings.push_back("spec:1:1: warning: short");
    for (int i = 0; i < 1500; ++i)
        run.warnings.push_back(std::string(2999, 'g') + "\xc3\xa9"); // ends in a 2-byte UTF-8
    envdesign::design_result_t sent = wire::result_message(problem, run);
    ASSERT_EQ(sent.warnings.size(), wire::MAX_WARNINGS);
    EXPECT_EQ(sent.num_warnings, static_cast<int>(wire::MAX_WARNINGS));
    EXPECT_EQ(sent.warnings[0], "spec:1:1: warning: short");
    EXPECT_EQ(sent.warnings[1], std::string(1024, 'g') + " ... (1977 bytes more)");
    EXPECT_EQ(sent.warnings.back(), "... and 502 more warnings");
    EXPECT_LT(bus::encode_message(sent).size(), 1100u * 1024);
    envdesign::design_result_t received;
    ASSERT_TRUE(bus::decode_message(bus::encode_message(sent), received));
    EXPECT_EQ(client::result_json_value(received).at("warnings").size(), wire::MAX_WARNINGS);
}

TEST(ResultFormat, NumbersForPeople) {
    EXPECT_EQ(client::shown(85.263215599), "85.26");
    EXPECT_EQ(client::shown(6.513215599000001), "6.513");
    EXPECT_EQ(client::shown(244), "244");
    EXPECT_EQ(client::shown(1234.56), "1234.6");
    EXPECT_EQ(client::shown(0.000123456), "0.0001235");
    EXPECT_EQ(client::shown(design::INF), "inf");
    EXPECT_EQ(client::json_number(design::INF), "inf");
    EXPECT_EQ(client::json_number(85.263215599).get<double>(), 85.263215599); // full precision
}

// pi = a b c d, other = a x c d y: common a c d; b only in pi, x and y only in the other.
TEST(ResultFormat, PlanDiffKeepsTheLongestCommonSteps) {
    auto diff = client::plan_diff({"a", "b", "c", "d"}, {"a", "x", "c", "d", "y"});
    std::string shown;
    for (const auto &s : diff)
        shown += (s.side == client::DiffSide::BOTH         ? " "
                  : s.side == client::DiffSide::ONLY_FIRST ? "+"
                                                           : "-") +
                 s.action;
    EXPECT_EQ(shown, " a+b-x c d-y");
    EXPECT_TRUE(client::plans_differ(diff));
    EXPECT_FALSE(client::plans_differ(client::plan_diff({"a", "b"}, {"a", "b"})));
    EXPECT_EQ(client::plan_diff({}, {"a"}).size(), 1u);
}

} // namespace
} // namespace envdesign::cluster
