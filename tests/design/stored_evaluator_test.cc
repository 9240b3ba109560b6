// The evaluation store: content keys, and a search answered from it.

#include "design/evaluation/stored_evaluator.h"
#include "example_paths.h"

#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

// Probabilities, task names and the objective's weights do not change what an evaluation
// is; the models, the modifications' edits and the distance do.
TEST(StoreKey, IgnoresWhatOnlyWeighs) {
    DesignProblem a = load_design_problem(RESTAURANT_DRIFT);
    DesignProblem b = a;
    b.tasks[0].probability = 0.2;
    b.tasks[0].name = "renamed";
    b.weights.alpha = 7;
    b.weights.beta = 0.5;
    b.weights.horizon = 9;
    b.modifications[0].cost = 100;
    b.modifications[0].name = "other-name";
    EXPECT_EQ(store_key(a), store_key(b));
    EXPECT_EQ(task_key(a, 0), task_key(b, 0));
    EXPECT_FALSE(task_key(a, 0) == task_key(a, 1));

    DesignProblem c = a;
    c.weights.distance = Distance::COST_DIFF;
    EXPECT_FALSE(store_key(a) == store_key(c));
    DesignProblem d = a;
    std::swap(d.modifications[0], d.modifications[1]); // indices mean other edits
    EXPECT_FALSE(store_key(a) == store_key(d));
    // The heuristic picks among plans of equal cost: its evaluations are its own.
    EXPECT_EQ(store_key(a, heuristics::HeuristicKind::LMCUT),
              store_key(b, heuristics::HeuristicKind::LMCUT));
    EXPECT_FALSE(store_key(a, heuristics::HeuristicKind::LMCUT) ==
                 store_key(a, heuristics::HeuristicKind::HMAX));
}

// A second problem with the same content (a task renamed, other weights) searched with a
// fresh LocalEvaluator but the first one's store: no planner run, no task evaluated.
TEST(StoredEvaluator, AnswersFromAnotherSearchesStore) {
    DesignProblem a = load_design_problem(RESTAURANT_DRIFT);
    EvaluationStore store;
    LocalEvaluator local_a(a, 1);
    StoredEvaluator stored_a(a, local_a, store);
    DesignResult first = search_design(a, stored_a, {});
    EXPECT_GT(first.counters.evaluator.planner_runs, 0);
    EXPECT_GT(store.size(), 0u);
    EXPECT_EQ(stored_a.stored_answers(), 0);

    DesignProblem b = a;
    b.tasks[1].name = "serve-booth-2";
    LocalEvaluator local_b(b, 1);
    StoredEvaluator stored_b(b, local_b, store);
    DesignResult second = search_design(b, stored_b, {});
    EXPECT_EQ(second.counters.evaluator.planner_runs, 0);
    EXPECT_EQ(second.counters.evaluator.task_evaluations, 0);
    EXPECT_EQ(second.best->ranked.configuration, first.best->ranked.configuration);
    EXPECT_DOUBLE_EQ(second.best->objective.value, first.best->objective.value);
    EXPECT_GT(stored_b.stored_answers(), 0);
}

// LIMIT answers say nothing and are not kept.
TEST(EvaluationStore, KeepsOnlyAnswers) {
    EvaluationStore store;
    TaskExplicability limit; // status LIMIT by default
    store.keep({0}, {1, 2}, limit);
    EXPECT_EQ(store.size(), 0u);
    TaskExplicability solved;
    solved.status = ExplicabilityStatus::SOLVED;
    solved.ie = 1;
    store.keep({0}, {1, 2}, solved);
    ASSERT_TRUE(store.find({0}, {1, 2}));
    EXPECT_EQ(store.find({0}, {1, 2})->ie, 1);
    EXPECT_FALSE(store.find({1}, {1, 2}));
    store.forget({1, 2});
    EXPECT_EQ(store.size(), 0u);
}

} // namespace
} // namespace envdesign::design

namespace envdesign::design {
namespace {

// A re-design after the task distribution drifted, on a warehouse floor (24 barriers, 10
// tasks) with the evaluations of the first search stored: the same answer as a fresh search
// of the drifted problem, without visiting more configurations than that one.
TEST(StoredEvaluator, WitnessSearchAfterDriftMatchesAFreshSearch) {
    DesignProblem problem = load_design_problem(std::string(ENVDESIGN_TEST_DATA) +
                                                "/design/warehouse-24/spec.textproto");
    EvaluationStore store;
    LocalEvaluator local(problem, 1);
    StoredEvaluator stored(problem, local, store);
    DesignResult first = search_design(problem, stored, {});
    ASSERT_TRUE(first.optimal);
    DesignProblem drifted = problem;
    std::swap(drifted.tasks[0].probability, drifted.tasks[9].probability);
    LocalEvaluator fresh_local(drifted, 1);
    DesignResult fresh = search_design(drifted, fresh_local, {});
    LocalEvaluator again_local(drifted, 1);
    StoredEvaluator again(drifted, again_local, store);
    DesignResult redesign = search_design(drifted, again, {});
    ASSERT_TRUE(fresh.optimal && redesign.optimal);
    EXPECT_EQ(redesign.best->ranked.configuration, fresh.best->ranked.configuration);
    EXPECT_NEAR(redesign.best->objective.value, fresh.best->objective.value, 1e-9);
    EXPECT_LE(
        redesign.counters.configurations_evaluated + redesign.counters.configurations_abandoned,
        2 * (fresh.counters.configurations_evaluated + fresh.counters.configurations_abandoned))
        << "fresh " << fresh.counters.configurations_evaluated;
    EXPECT_LT(redesign.counters.evaluator.task_evaluations,
              fresh.counters.evaluator.task_evaluations);
}

} // namespace
} // namespace envdesign::design
