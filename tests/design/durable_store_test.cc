// Durable evaluation stores (evaluation_store.h over store/record_db.h): records that read
// back as written, names that change with what the record means, and a search answered from
// a file another store wrote.

#include "design/evaluation/evaluation_record.h"
#include "design/evaluation/local_evaluator.h"
#include "design/evaluation/stored_evaluator.h"
#include "design/search/design_search.h"
#include "example_paths.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <unistd.h>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

namespace fs = std::filesystem;

TaskExplicability solved() {
    TaskExplicability e;
    e.status = ExplicabilityStatus::SOLVED;
    e.ie = 2.718281828459045;
    e.robot_cost = 7;
    e.human_plan_cost = 6;
    e.human_optimal_cost = 5;
    e.plan = {"(move c00 c10)", "(move c10 c11)"};
    e.human_plan = std::vector<std::string>{"(move c00 c01)"};
    return e;
}

void expect_equal(const TaskExplicability &a, const TaskExplicability &b) {
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.ie, b.ie);
    EXPECT_EQ(a.robot_cost, b.robot_cost);
    EXPECT_EQ(a.human_plan_cost, b.human_plan_cost);
    EXPECT_EQ(a.human_optimal_cost, b.human_optimal_cost);
    EXPECT_EQ(a.plan, b.plan);
    EXPECT_EQ(a.human_plan, b.human_plan);
}

TEST(EvaluationRecord, ReadsBackWhatWasWritten) {
    expect_equal(*decode_evaluation(encode_evaluation(solved())), solved());
    TaskExplicability none; // P_mod has no plan: infinities, no human plan known
    none.status = ExplicabilityStatus::INEXPLICABLE;
    none.human_optimal_cost = INF;
    expect_equal(*decode_evaluation(encode_evaluation(none)), none);
    EXPECT_EQ(decode_robot_bound(encode_robot_bound({12.5, std::nullopt}))->cost, 12.5);
    EXPECT_EQ(decode_robot_bound(encode_robot_bound({INF, std::nullopt}))->cost, INF);
    EXPECT_FALSE(
        decode_robot_bound(encode_robot_bound({12.5, std::nullopt}))->ie_floor); // a record without
    auto floored = decode_robot_bound(encode_robot_bound({12, std::exp(4.0)}));
    ASSERT_TRUE(floored && floored->ie_floor);
    EXPECT_EQ(*floored->ie_floor, std::exp(4.0));
    EXPECT_FALSE(floored->explanation_floor);
    // The explaining robot's explanation floor is appended after the IE floor: a record
    // without it reads as before, and one with it keeps it.
    std::string with = encode_robot_bound({12, std::exp(4.0), 3});
    EXPECT_EQ(with.substr(0, encode_robot_bound({12, std::exp(4.0)}).size()),
              encode_robot_bound({12, std::exp(4.0)}));
    auto told = decode_robot_bound(with);
    ASSERT_TRUE(told && told->explanation_floor);
    EXPECT_EQ(*told->explanation_floor, 3);
    std::string forged = with;
    forged[forged.size() - 1] = '\x7f'; // a count far above any model's differences
    EXPECT_FALSE(decode_robot_bound(forged));
}

// COST_OPTIMAL modes keep every action of the optimal plans (the witnesses); the records of
// the other modes stay byte for byte what they were.
TEST(EvaluationRecord, KeepsTheOptimalActionsOfCostOptimalModes) {
    TaskExplicability e = solved();
    std::string without = encode_evaluation(e);
    e.optimal_actions = std::vector<std::string>{"(move c00 c10)", "(move c10 c11)", "(wait)"};
    std::string with = encode_evaluation(e);
    EXPECT_EQ(with.substr(0, without.size()), without);
    auto back = decode_evaluation(with);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->optimal_actions, e.optimal_actions);
    EXPECT_FALSE(decode_evaluation(without)->optimal_actions);
    EXPECT_FALSE(decode_evaluation(with.substr(0, with.size() - 1)));
}

TEST(EvaluationRecord, RefusesWhatItDidNotWrite) {
    std::string bytes = encode_evaluation(solved());
    EXPECT_FALSE(decode_evaluation(bytes.substr(0, bytes.size() - 1))); // cut short
    EXPECT_FALSE(decode_evaluation(bytes + "x"));                       // trailing bytes
    std::string other_version = bytes;
    other_version[0] = static_cast<char>(RECORD_VERSION + 1);
    EXPECT_FALSE(decode_evaluation(other_version));
    EXPECT_FALSE(decode_robot_bound(bytes)); // a record of the other kind
    EXPECT_FALSE(decode_evaluation(encode_robot_bound({3, std::nullopt})));
}

TEST(EvaluationRecord, NamesChangeWithWhatTheRecordMeans) {
    TaskKey scope = digest_key("scope"), task = digest_key("task");
    auto name = record_name(RecordKind::EXPLICABILITY, scope, {0, 2}, task);
    EXPECT_EQ(name, record_name(RecordKind::EXPLICABILITY, scope, {0, 2}, task));
    EXPECT_NE(name, record_name(RecordKind::ROBOT_BOUND, scope, {0, 2}, task));
    EXPECT_NE(name, record_name(RecordKind::EXPLICABILITY, digest_key("x"), {0, 2}, task));
    EXPECT_NE(name, record_name(RecordKind::EXPLICABILITY, scope, {0, 1}, task));
    EXPECT_NE(name, record_name(RecordKind::EXPLICABILITY, scope, {2}, task));
    EXPECT_NE(name, record_name(RecordKind::EXPLICABILITY, scope, {0, 2}, digest_key("y")));
}

class DurableStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("envdesign-durable-store-" + std::to_string(getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::shared_ptr<store::RecordDb> open() {
        store::RecordDbOptions options;
        options.sync = false;
        return std::make_shared<store::RecordDb>((dir / "evaluations.db").string(), options);
    }
    fs::path dir;
};

// A search over a durable store; the process "restarts" (new file handle, new store, new
// evaluator): the same problem is answered from the file without a planner.
TEST_F(DurableStoreTest, ASearchIsAnsweredFromTheFileAfterReopening) {
    DesignProblem problem = load_design_problem(RESTAURANT_DRIFT);
    TaskKey scope = store_key(problem, heuristics::HeuristicKind::LMCUT);
    DesignResult first;
    {
        EvaluationStore store(open(), scope);
        LocalEvaluator local(problem, 1);
        StoredEvaluator stored(problem, local, store);
        first = search_design(problem, stored, {});
        EXPECT_GT(first.counters.evaluator.planner_runs, 0);
    }
    auto db = open();
    EXPECT_GT(db->report().records, 0u);
    EvaluationStore store(db, scope);
    EXPECT_EQ(store.size(), 0u); // nothing in memory yet: all of it comes from the file
    DesignProblem reweighted = problem;
    reweighted.tasks[0].probability = 0.9;
    reweighted.tasks[1].probability = 0.1;
    LocalEvaluator local(reweighted, 1);
    StoredEvaluator stored(reweighted, local, store);
    DesignResult second = search_design(reweighted, stored, {});
    EXPECT_EQ(second.counters.evaluator.planner_runs, 0);
    EXPECT_GT(stored.stored_answers(), 0);

    // Another heuristic is another scope: its plans are its own.
    EvaluationStore hmax(db, store_key(problem, heuristics::HeuristicKind::HMAX));
    LocalEvaluator local_hmax(problem, 1);
    StoredEvaluator stored_hmax(problem, local_hmax, hmax);
    EXPECT_GT(search_design(problem, stored_hmax, {}).counters.evaluator.planner_runs, 0);
}

// What keep() returned from is in the file, before any search finished.
TEST_F(DurableStoreTest, KeptEntriesAreInTheFileAtOnce) {
    DesignProblem problem = load_design_problem(RESTAURANT_DRIFT);
    TaskKey scope = store_key(problem, heuristics::HeuristicKind::LMCUT);
    TaskKey task = task_key(problem, 0);
    EvaluationStore writer(open(), scope);
    writer.keep({1}, task, solved());
    writer.keep_robot_bound({1}, task, {4, 20.0});
    TaskExplicability limit;
    writer.keep({2}, task, limit);         // LIMIT: nothing to keep
    EvaluationStore reader(open(), scope); // a second handle, as after a restart
    expect_equal(*reader.find({1}, task), solved());
    ASSERT_TRUE(reader.find_robot_bound({1}, task));
    EXPECT_EQ(reader.find_robot_bound({1}, task)->cost, 4);
    EXPECT_EQ(reader.find_robot_bound({1}, task)->ie_floor, 20.0);
    EXPECT_FALSE(reader.find({2}, task));
    EXPECT_FALSE(reader.find({1}, task_key(problem, 1)));
}

} // namespace
} // namespace envdesign::design
