// The witness search on generated warehouse floors (tests/benchmarks/design_scale/
// generate.py): every modification is a barrier that restricts, so its pooled-plan bounds,
// probes and reuse of equally cheap plans all run (with the hitting-set phase off), and the
// hitting-set phase proves the answer (on); the exhaustive search is the reference.

#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

class WarehouseAgreement : public ::testing::TestWithParam<const char *> {};

TEST_P(WarehouseAgreement, SameDesignAsEverySubset) {
    DesignProblem problem = load_design_problem(std::string(ENVDESIGN_TEST_DATA) + "/design/" +
                                                GetParam() + "/spec.textproto");
    DesignSearchOptions exhaustive;
    exhaustive.method = SearchMethod::EXHAUSTIVE;
    LocalEvaluator every(problem, 1);
    DesignResult want = search_design(problem, every, exhaustive);
    ASSERT_TRUE(want.optimal);
    EXPECT_FALSE(want.best->ranked.configuration.empty()); // a floor where barriers pay
    for (bool hitting_sets : {false, true}) {
        SCOPED_TRACE(hitting_sets ? "hitting-set phase" : "best-first search alone");
        DesignSearchOptions witness;
        witness.hitting_sets = hitting_sets;
        LocalEvaluator witnessed(problem, 1);
        DesignResult got = search_design(problem, witnessed, witness);
        ASSERT_TRUE(got.optimal);
        EXPECT_EQ(got.best->ranked.configuration, want.best->ranked.configuration);
        EXPECT_NEAR(got.best->objective.value, want.best->objective.value, 1e-9);
        // Every barrier restricts: none is weighed with every design; the phase proves it or not.
        bool proven = false;
        for (const std::string &note : got.notes) {
            EXPECT_EQ(note.find("weighs it with every design"), std::string::npos) << note;
            proven =
                proven || note.find("proven optimal by the hitting-set phase") != std::string::npos;
        }
        EXPECT_EQ(proven, hitting_sets);
        EXPECT_LT(got.counters.configurations_evaluated,
                  want.counters.configurations_evaluated + want.counters.configurations_abandoned);
    }
}

// The 5 best, the same from every search (docs/design-search.md "Ranking"). On this floor
// (the smaller one, to keep ctest fast) the best closes the racks from the dock side (26.24);
// second, the same from the other side (a tie); then the best plus one barrier that no plan
// uses (27.24, three of them in spec order): members of the best's cone, which the witness
// search never plans.
TEST(WarehouseRanking, SameRankingAsEverySubset) {
    DesignProblem problem = load_design_problem(std::string(ENVDESIGN_TEST_DATA) +
                                                "/design/warehouse-10x3-s2/spec.textproto");
    DesignSearchOptions exhaustive;
    exhaustive.method = SearchMethod::EXHAUSTIVE;
    exhaustive.ranking = 5;
    exhaustive.ranking_all = true; // ranks 3-5 are padded: the default leaves them out
    LocalEvaluator every(problem, 1);
    DesignResult want = search_design(problem, every, exhaustive);
    ASSERT_TRUE(want.optimal);
    ASSERT_EQ(want.ranking.size(), 5u);
    EXPECT_NEAR(want.ranking[1].objective, want.ranking[0].objective, 1e-9);
    for (std::size_t i = 2; i < 5; ++i) {
        EXPECT_NEAR(want.ranking[i].objective, want.ranking[0].objective + 1, 1e-9);
        EXPECT_EQ(want.ranking[i].configuration.size(), want.ranking[0].configuration.size() + 1);
    }
    for (bool hitting_sets : {false, true}) {
        SCOPED_TRACE(hitting_sets ? "hitting-set phase" : "best-first search alone");
        DesignSearchOptions witness;
        witness.hitting_sets = hitting_sets;
        witness.ranking = 5;
        witness.ranking_all = true;
        LocalEvaluator witnessed(problem, 1);
        DesignResult got = search_design(problem, witnessed, witness);
        ASSERT_TRUE(got.optimal);
        ASSERT_EQ(got.ranking.size(), 5u);
        for (std::size_t i = 0; i < 5; ++i) {
            EXPECT_EQ(got.ranking[i].configuration, want.ranking[i].configuration) << i + 1;
            EXPECT_NEAR(got.ranking[i].objective, want.ranking[i].objective, 1e-9) << i + 1;
        }
    }
    // By default ranks 3-5 (the best plus a barrier no plan uses) are left out: the two best
    // stay, and no design listed holds one of them plus one modification.
    exhaustive.ranking_all = false;
    LocalEvaluator every_again(problem, 1);
    DesignResult paying = search_design(problem, every_again, exhaustive);
    DesignSearchOptions witness;
    witness.ranking = 5;
    LocalEvaluator witnessed(problem, 1);
    DesignResult got = search_design(problem, witnessed, witness);
    ASSERT_EQ(paying.ranking.size(), 5u);
    ASSERT_EQ(got.ranking.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(got.ranking[i].configuration, paying.ranking[i].configuration) << i + 1;
        const Configuration &c = paying.ranking[i].configuration;
        for (std::size_t best = 0; best < 2 && i >= 2; ++best) {
            const Configuration &b = want.ranking[best].configuration;
            EXPECT_FALSE(c.size() == b.size() + 1 &&
                         std::includes(c.begin(), c.end(), b.begin(), b.end()))
                << "rank " << i + 1 << " is rank " << best + 1 << " padded";
        }
    }
    EXPECT_EQ(paying.ranking[0].configuration, want.ranking[0].configuration);
    EXPECT_EQ(paying.ranking[1].configuration, want.ranking[1].configuration);
}

INSTANTIATE_TEST_SUITE_P(Floors, WarehouseAgreement,
                         ::testing::Values("warehouse-10x3-s2", "warehouse-12x10-s1"));

} // namespace
} // namespace envdesign::design
