// The coordinator's stores of evaluations across requests: one per (models, modifications,
// distance, heuristic), the least recently used dropped first when there are too many.

#include "harness.h"

#include "cluster/evaluation_stores.h"

#include <filesystem>
#include <unistd.h>

namespace envdesign::cluster::testing {
namespace {

design::TaskExplicability solved(double ie) {
    design::TaskExplicability e;
    e.status = design::ExplicabilityStatus::SOLVED;
    e.ie = ie;
    e.robot_cost = 7;
    return e;
}

class EvaluationStoresTest : public ::testing::Test {
protected:
    design::DesignProblem restaurant =
        spec::load_design_problem(in_repo("examples/restaurant/c-two-tasks-t10.textproto"));
    design::DesignProblem blocks =
        spec::load_design_problem(in_repo("examples/blocksworld/design.textproto"));
};

TEST_F(EvaluationStoresTest, SameModelsShareAStoreWhateverTheDistribution) {
    EvaluationStores stores(100);
    design::DesignProblem skewed = restaurant;
    skewed.tasks[0].probability = 0.9;
    skewed.tasks[1].probability = 0.1;
    skewed.weights.horizon = 3;
    EXPECT_EQ(stores.store_for(restaurant, 0), stores.store_for(skewed, 0));
    EXPECT_NE(stores.store_for(restaurant, 0), stores.store_for(restaurant, 1)); // heuristic
    EXPECT_NE(stores.store_for(restaurant, 0), stores.store_for(blocks, 0));
    design::DesignProblem fewer = restaurant;
    fewer.modifications.pop_back(); // configuration indices would mean other things
    EXPECT_NE(stores.store_for(restaurant, 0), stores.store_for(fewer, 0));
    EXPECT_EQ(stores.stores(), 4u);
}

TEST_F(EvaluationStoresTest, TrimDropsTheLeastRecentlyUsed) {
    EvaluationStores stores(4);
    auto key = design::task_key(restaurant, 0);
    auto first = stores.store_for(restaurant, 0);
    first->keep({0}, key, solved(1));
    first->keep({1}, key, solved(2));
    first->keep_robot_bound({2}, key, {9, std::nullopt}); // bounds count too
    auto second = stores.store_for(blocks, 0);
    second->keep({0}, design::task_key(blocks, 0), solved(3));
    stores.trim();
    EXPECT_EQ(stores.stores(), 2u);  // 4 records: nothing to drop
    stores.store_for(restaurant, 0); // the restaurant is now the most recent
    second->keep({1}, design::task_key(blocks, 0), solved(4));
    stores.trim(); // 5 records, but searches still hold both stores
    EXPECT_EQ(stores.stores(), 2u);
    second.reset(); // that search ended
    stores.trim();  // the blocks store goes, the least recently used
    EXPECT_EQ(stores.stores(), 1u);
    EXPECT_EQ(stores.store_for(restaurant, 0), first);
    EXPECT_EQ(stores.store_for(restaurant, 0)->find({1}, key)->ie, 2);
    EXPECT_EQ(stores.store_for(blocks, 0)->size(), 0u); // made anew
}

// With a state file, a new set of stores (a restarted coordinator) finds what the old one
// kept, in the store of the same models and heuristic only.
TEST_F(EvaluationStoresTest, StoresOverAStateFileOutliveTheirProcess) {
    auto dir =
        std::filesystem::temp_directory_path() / ("envdesign-stores-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    auto open = [&] {
        store::RecordDbOptions options;
        options.sync = false;
        return std::make_shared<store::RecordDb>((dir / "evaluations.db").string(), options);
    };
    auto key = design::task_key(restaurant, 0);
    {
        EvaluationStores before(100, open());
        before.store_for(restaurant, 0)->keep({1}, key, solved(5));
        before.store_for(restaurant, 0)->keep_robot_bound({1}, key, {6, std::nullopt});
    }
    EvaluationStores after(100, open());
    auto store = after.store_for(restaurant, 0);
    ASSERT_TRUE(store->find({1}, key));
    EXPECT_EQ(store->find({1}, key)->ie, 5);
    EXPECT_EQ(store->find_robot_bound({1}, key)->cost, 6);
    EXPECT_FALSE(after.store_for(restaurant, 1)->find({1}, key)); // another heuristic
    EXPECT_FALSE(store->find({0}, key));
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace envdesign::cluster::testing
