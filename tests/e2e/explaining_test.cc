// robot_behaviour EXPLAINING through the deployed services: envdesign-coordinator and two
// envdesign-planner processes on loopback udpm. The explanations cross the wire in the
// planners' answers (evaluation_t) and in the result (task_result_t): the cluster's JSON
// equals the self-contained run's, and says which option each task takes and why.

#include "local_cluster.h"

#include <envdesign/client/client.h>

#include <cmath>

namespace envdesign::e2e {
namespace {

const char *EXPLAINING = "examples/restaurant/c-two-tasks-t10-explaining.textproto";

// Both tasks explain the same two closed passages (tests/design/minimal_explanation_test.cc):
// objective 3 H + 18.75 with H = (1 - 0.9^10) / 0.1, explanation term 2 H.
TEST(EndToEndExplaining, RestaurantThroughTheCoordinator) {
    LocalCluster cluster(2);
    client::Options options;
    options.give_up_after_s = 10;
    client::Result result = client::run_design_remote(source(EXPLAINING), cluster.url(), options);
    ASSERT_EQ(result.exit_code, 0) << result.error << cluster.logs();
    nlohmann::json got = nlohmann::json::parse(result.json);
    expect_same_design(got, self_contained(source(EXPLAINING)));
    double h = (1 - std::pow(0.9, 10)) / 0.1;
    EXPECT_NEAR(got.at("objective").get<double>(), 3 * h + 18.75, 1e-9);
    EXPECT_NEAR(got.at("terms").at("explanation").get<double>(), 2 * h, 1e-9);
    EXPECT_EQ(got.at("design"), nlohmann::json::array());
    ASSERT_EQ(got.at("tasks").size(), 2u);
    for (const auto &task : got.at("tasks")) {
        EXPECT_EQ(task.at("option"), "explain");
        EXPECT_EQ(task.at("ie"), 1);
        EXPECT_EQ(task.at("explanation"),
                  nlohmann::json({"-init (connected c00 c01)", "-init (connected c10 c11)"}));
    }
    EXPECT_EQ(got.at("tasks")[1].at("robot_optimal_cost"), 8);
    EXPECT_GT(got.at("cluster").at("planners_used").get<int>(), 0);
}

} // namespace
} // namespace envdesign::e2e
