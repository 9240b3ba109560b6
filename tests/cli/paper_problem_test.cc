// One of the paper-evaluation design problems (tests/data/paper, made by
// tests/benchmarks/paper/generate_design_problems.py) as a CI check of the whole chain.
// Expected values from the committed benchmark run (docs/results/table1-runs.csv), where the
// search proved them optimal over all 2^k configurations.

#include "run_command.h"

#include <gtest/gtest.h>

namespace envdesign::testing {
namespace {

TEST(PaperProblem, DriverlogOneAtHorizonOneChoosesTheDisembarkRule) {
    std::string spec = std::string(ENVDESIGN_TEST_DATA) + "/paper/driverlog/01/design-t1.textproto";
    CommandResult r = run_envdesign("design --json --workers 1 " + spec, false);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("\"status\":\"optimal\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"design\":[\"disembark-rule-s2\"]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"objective\":3.75"), std::string::npos) << r.out;
}

} // namespace
} // namespace envdesign::testing
