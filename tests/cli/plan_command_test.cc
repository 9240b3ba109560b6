// `envdesign plan` as a process: output format, JSON and the exit codes of SPEC.md.

#include "run_command.h"

#include <gtest/gtest.h>

#include <chrono>

namespace envdesign::testing {
namespace {

const std::string IPC = std::string(ENVDESIGN_SHARED_DIR) + "/benchmarks/ipc/";

TEST(PlanCommand, PrintsTheOptimalPlanInSasPlanFormat) {
    CommandResult r =
        run_envdesign("plan " + DATA + "/tiny/domain.pddl " + DATA + "/tiny/problem.pddl", false);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out, "(move r1 kitchen hub)\n(unlock r1 lab)\n(move r1 hub lab)\n"
                     "; cost = 9 (general cost)\n");
}

TEST(PlanCommand, UnitCostDomainsSayUnitCost) {
    CommandResult r = run_envdesign(
        "plan " + IPC + "blocks/domain.pddl " + IPC + "blocks/probBLOCKS-4-0.pddl", false);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("; cost = 6 (unit cost)\n"), std::string::npos) << r.out;
}

// Liberties that Fast Downward's translator accepts (tests/data/liberties, issue 12): planned,
// with the optimal cost Fast Downward's astar(lmcut()) finds on the same files.
TEST(PlanCommand, PlansDomainsThatTakeLiberties) {
    const std::string dir = DATA + "/liberties/";
    struct Case {
        std::string name;
        std::string cost_line;
    };
    for (const Case &c : {Case{"type-listed-twice", "; cost = 2 (unit cost)"},
                          Case{"variable-glued", "; cost = 1 (unit cost)"},
                          Case{"sections-any-order", "; cost = 2 (unit cost)"},
                          Case{"beyond-requirements", "; cost = 4 (general cost)"},
                          Case{"init-listed-false", "; cost = 3 (general cost)"},
                          Case{"double-negation", "; cost = 1 (unit cost)"},
                          Case{"predicate-declared-twice", "; cost = 2 (unit cost)"},
                          Case{"dangling-type", "; cost = 1 (unit cost)"},
                          // the road without a length is not taken: 3 + 4, not 0
                          Case{"undefined-cost", "; cost = 7 (general cost)"}}) {
        CommandResult r = run_envdesign(
            "plan " + dir + c.name + "-domain.pddl " + dir + c.name + "-problem.pddl", false);
        EXPECT_EQ(r.exit_code, 0) << c.name << ": " << r.out;
        EXPECT_NE(r.out.find(c.cost_line + "\n"), std::string::npos) << c.name << ": " << r.out;
    }
}

// Without the metric the cost terms are not read: the road without a length is taken.
TEST(PlanCommand, WithoutTheMetricAnUndefinedCostIsNotRead) {
    const std::string dir = DATA + "/liberties/";
    CommandResult r = run_envdesign("plan " + dir + "undefined-cost-domain.pddl " + dir +
                                        "undefined-cost-no-metric-problem.pddl",
                                    false);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.out, "(drive a c)\n; cost = 1 (unit cost)\n");
}

TEST(PlanCommand, ProvenUnsolvableExitsThree) {
    CommandResult r = run_envdesign(
        "plan --json " + DATA + "/bad/ok-domain.pddl " + DATA + "/unsolvable-problem.pddl", false);
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.out.find("\"status\":\"unsolvable\""), std::string::npos) << r.out;
}

TEST(PlanCommand, TimeLimitExitsFour) {
    // FD needs 248336 expansions here; a tenth of a second is far too little.
    CommandResult r = run_envdesign("plan --json --time-limit 0.1 " + IPC + "blocks/domain.pddl " +
                                        IPC + "blocks/probBLOCKS-10-0.pddl",
                                    false);
    EXPECT_EQ(r.exit_code, 4);
    EXPECT_NE(r.out.find("\"status\":\"limit\""), std::string::npos) << r.out;
}

TEST(PlanCommand, TimeLimitHoldsWhileGrounding) {
    // 40 960 000 reachable actions: grounding alone would take minutes and gigabytes.
    auto start = std::chrono::steady_clock::now();
    CommandResult r =
        run_envdesign("plan --json --time-limit 0.5 " + DATA + "/huge-grounding/domain.pddl " +
                          DATA + "/huge-grounding/problem.pddl",
                      false);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 4);
    EXPECT_NE(r.out.find("\"status\":\"limit\""), std::string::npos) << r.out;
    EXPECT_LT(seconds, 30); // stopped by the limit, not by finishing
}

TEST(PlanCommand, JsonCarriesCostAndSearchStatistics) {
    CommandResult r = run_envdesign(
        "plan --json " + IPC + "blocks/domain.pddl " + IPC + "blocks/probBLOCKS-4-0.pddl", false);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("\"cost\":6"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"status\":\"solved\""), std::string::npos) << r.out;
    // FD's astar(lmcut()) expands 7 states on this instance (optimal-costs.csv).
    EXPECT_NE(r.out.find("\"expansions\":7"), std::string::npos) << r.out;
}

} // namespace
} // namespace envdesign::testing
