// The witness search on generated warehouse floors (tests/benchmarks/design_scale/
// generate.py): every modification is a barrier that restricts, so its pooled-plan bounds,
// probes and reuse of equally cheap plans all run; the exhaustive search is the reference.

#include "design/design_search.h"
#include "design/design_spec.h"
#include "design/local_evaluator.h"

#include <gtest/gtest.h>

namespace envdesign::design {
namespace {

class WarehouseAgreement : public ::testing::TestWithParam<const char *> {};

TEST_P(WarehouseAgreement, SameDesignAsEverySubset) {
    DesignProblem problem = load_design_problem(std::string(ENVDESIGN_TEST_DATA) + "/design/" +
                                                GetParam() + "/spec.textproto");
    DesignSearchOptions exhaustive;
    exhaustive.method = SearchMethod::EXHAUSTIVE;
    LocalEvaluator every(problem, 1), witnessed(problem, 1);
    DesignResult want = search_design(problem, every, exhaustive);
    DesignResult got = search_design(problem, witnessed, {});
    ASSERT_TRUE(want.optimal && got.optimal);
    EXPECT_EQ(got.best->ranked.configuration, want.best->ranked.configuration);
    EXPECT_NEAR(got.best->objective.value, want.best->objective.value, 1e-9);
    EXPECT_FALSE(want.best->ranked.configuration.empty()); // a floor where barriers pay
    EXPECT_TRUE(got.notes.empty());                        // every barrier restricts
    EXPECT_LT(got.counters.configurations_evaluated,
              want.counters.configurations_evaluated + want.counters.configurations_abandoned);
}

INSTANTIATE_TEST_SUITE_P(Floors, WarehouseAgreement,
                         ::testing::Values("warehouse-10x3-s2", "warehouse-12x10-s1"));

} // namespace
} // namespace envdesign::design
