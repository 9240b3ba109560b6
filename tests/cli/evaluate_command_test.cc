// `envdesign evaluate` and the explained result of `envdesign design`, through the built
// binary (restaurant, setting (c); the values are worked out in tests/design/explanation_test.cc).

#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iterator>

namespace envdesign::testing {
namespace {

const std::string SPEC = std::string(ENVDESIGN_EXAMPLES) + "/restaurant/c-two-tasks-t10.textproto";

double f10() { return (1 - std::pow(0.9, 10)) / 0.1; } // 6.5132156

nlohmann::json json_of(const std::string &arguments) {
    CommandResult r = run_envdesign(arguments, false);
    EXPECT_EQ(r.exit_code, 0) << arguments << "\n" << r.out;
    return nlohmann::json::parse(r.out);
}

// The weighted terms add up to the objective, and are the unweighted ones times the weights.
void expect_terms_add_up(const nlohmann::json &result) {
    const auto &w = result.at("weighted_terms");
    double sum = w.at("inexplicability").get<double>() + w.at("design_cost").get<double>() +
                 w.at("robot_cost").get<double>();
    EXPECT_NEAR(sum, result.at("objective").get<double>(), 1e-9);
    EXPECT_NEAR(w.at("design_cost").get<double>(),
                30 * result.at("terms").at("design_cost").get<double>(), 1e-9);
    EXPECT_NEAR(w.at("robot_cost").get<double>(),
                0.25 * result.at("terms").at("robot_cost").get<double>(), 1e-9);
}

// {00-01}: IE e^2 for both tasks: e^2 f_10 + 30 + 18.75 = 96.8765; without its one
// modification it is the empty design, (e^2 + e^4)/2 f_10 + 18.75 = 220.6180.
TEST(EvaluateCommand, KnownDesign) {
    nlohmann::json r = json_of("evaluate " + SPEC + " --design barrier-00-01 --json");
    double e2 = std::exp(2.0), e4 = std::exp(4.0);
    EXPECT_EQ(r.at("status"), "evaluated");
    EXPECT_EQ(r.at("design"), nlohmann::json::array({"barrier-00-01"}));
    EXPECT_NEAR(r.at("objective").get<double>(), e2 * f10() + 30 + 18.75, 1e-9);
    EXPECT_NEAR(r.at("baseline").at("objective").get<double>(), (e2 + e4) / 2 * f10() + 18.75,
                1e-9);
    expect_terms_add_up(r);
    EXPECT_NEAR(r.at("least_inexplicability").get<double>(), f10(), 1e-9);
    const auto &marginal = r.at("explanation").at("marginal");
    ASSERT_EQ(marginal.size(), 1u);
    EXPECT_NEAR(marginal[0].at("value").get<double>(), (e2 + e4) / 2 * f10() - e2 * f10() - 30,
                1e-9); // negative: it pays off
    EXPECT_EQ(r.at("tasks").size(), 2u);
    EXPECT_NEAR(r.at("tasks")[1].at("ie").get<double>(), e2, 1e-9);
}

TEST(EvaluateCommand, EmptyDesignAndUnknownName) {
    nlohmann::json r = json_of("evaluate " + SPEC + " --design '' --json");
    EXPECT_EQ(r.at("design"), nlohmann::json::array());
    EXPECT_EQ(r.at("objective"), r.at("baseline").at("objective"));
    CommandResult bad = run_envdesign("evaluate " + SPEC + " --design barrier-00-01,barrier-7");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.out.find("'barrier-7'"), std::string::npos) << bad.out;
}

// `design` explains its answer: per task the empty design beside the chosen one, the plans,
// the value of each chosen modification, and break-even (T = 6, alpha = 0.72092).
TEST(DesignCommand, ExplainsTheRestaurant) {
    nlohmann::json r = json_of("design " + SPEC + " --json");
    expect_terms_add_up(r);
    const auto &e = r.at("explanation");
    EXPECT_EQ(e.at("break_even").at("horizon_down").at("at"), 6);
    EXPECT_NEAR(e.at("break_even").at("alpha_down").at("at").get<double>(), 0.72092, 1e-5);
    ASSERT_EQ(e.at("marginal").size(), 2u);
    EXPECT_NEAR(e.at("marginal")[1].at("value").get<double>(), 11.6133, 1e-4);
    const auto &g2 = e.at("tasks")[1];
    EXPECT_NEAR(g2.at("baseline").at("ie").get<double>(), std::exp(4.0), 1e-9);
    EXPECT_EQ(g2.at("chosen").at("ie"), 1);
    EXPECT_EQ(g2.at("robot_plan").size(), 8u);
    EXPECT_EQ(g2.at("explicable_plan"), r.at("tasks")[1].at("plan"));
    // Text: rounded numbers, not 17 digits.
    CommandResult text = run_envdesign("design " + SPEC, false);
    EXPECT_NE(text.out.find("objective: 85.26 = 6.513 inexplicability"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("barrier-10-11: 96.88 without it (+11.61)"), std::string::npos);
}

// robot_behaviour EXPLAINING (restaurant, x = 1; tests/design/explaining_test.cc): no design,
// both tasks explain the two closed passages, 38.2896 = f_10 + 18.75 + 2 f_10 (two differences
// told on every repetition). The weighted terms, with the explanation term, add up; the page
// names the option and the differences; break-even is not claimed for this mode.
TEST(ReportCommand, ExplainingRobotShowsItsExplanations) {
    const std::string spec =
        std::string(ENVDESIGN_EXAMPLES) + "/restaurant/c-two-tasks-t10-explaining.textproto";
    nlohmann::json r = json_of("design " + spec + " --json");
    EXPECT_EQ(r.at("design"), nlohmann::json::array());
    EXPECT_NEAR(r.at("objective").get<double>(), f10() + 18.75 + 2 * f10(), 1e-6);
    const auto &w = r.at("weighted_terms");
    EXPECT_NEAR(w.at("inexplicability").get<double>() + w.at("design_cost").get<double>() +
                    w.at("robot_cost").get<double>() + w.at("explanation").get<double>(),
                r.at("objective").get<double>(), 1e-9);
    for (const auto &task : r.at("tasks")) {
        EXPECT_EQ(task.at("option"), "explain");
        EXPECT_EQ(task.at("explanation"),
                  (nlohmann::json{"-init (connected c00 c01)", "-init (connected c10 c11)"}));
    }
    std::string page = ::testing::TempDir() + "/explaining-report.html";
    CommandResult report = run_envdesign("report " + spec + " -o " + page, false);
    ASSERT_EQ(report.exit_code, 0) << report.out;
    std::ifstream in(page);
    std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("follows its own plan and explains"), std::string::npos);
    EXPECT_NE(html.find("<code>-init (connected c10 c11)</code>"), std::string::npos);
    EXPECT_NE(html.find("Not computed: with robot_behaviour EXPLAINING"), std::string::npos);
}

} // namespace
} // namespace envdesign::testing
