// The dispatcher's job order: robot bounds first, then `abandon`, then explicability jobs.

#include "design/evaluation/dispatcher.h"

#include <gtest/gtest.h>

namespace envdesign::design {
namespace {

TaskExplicability solved(double ie) {
    TaskExplicability t;
    t.status = ExplicabilityStatus::SOLVED;
    t.ie = ie;
    t.robot_cost = 1;
    return t;
}

struct Recorder {
    std::vector<ConfigurationEvaluation> done;
    EvaluationCallbacks callbacks;
};

TEST(Dispatcher, BoundsFirstThenAbandonBeforeAnyCompiledTask) {
    Recorder r;
    // Abandon a configuration once its robot bounds are known and sum to more than 10.
    r.callbacks.abandon = [](const ConfigurationEvaluation &e) {
        double sum = 0;
        for (const auto &b : e.robot_cost_bounds)
            sum += b.value_or(0);
        return sum > 10;
    };
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    Dispatcher d({unevaluated({}), unevaluated({0})}, 2, true, false, r.callbacks);
    auto answer_bound = [&](Job job, double bound) { d.receive({job, bound, std::nullopt, {}}); };
    // Both bounds of {} go out before anything else of it; {0}'s follow while they are away.
    std::vector<Job> sent;
    for (int i = 0; i < 4; ++i)
        sent.push_back(*d.next_job());
    for (const auto &job : sent)
        EXPECT_EQ(job.kind, JobKind::ROBOT_BOUND);
    EXPECT_EQ(sent[2].configuration, 1);
    EXPECT_FALSE(d.next_job()); // everything waits for answers
    answer_bound(sent[2], 8);
    answer_bound(sent[3], 8); // {0}: 16 > 10: abandoned, no compiled task solved
    ASSERT_EQ(r.done.size(), 1u);
    EXPECT_EQ(r.done[0].status, EvaluationStatus::CUT_OFF);
    EXPECT_EQ(r.done[0].configuration, Configuration{0});
    answer_bound(sent[0], 3);
    answer_bound(sent[1], 3);
    Job first = *d.next_job();
    Job second = *d.next_job();
    EXPECT_EQ(first.kind, JobKind::EXPLICABILITY);
    EXPECT_EQ(second.task, 1);
    EXPECT_FALSE(d.next_job());
    d.receive({first, std::nullopt, std::nullopt, solved(1)});
    d.receive({second, std::nullopt, std::nullopt, solved(2)});
    ASSERT_EQ(r.done.size(), 2u);
    EXPECT_EQ(r.done[1].status, EvaluationStatus::COMPLETE);
    EXPECT_EQ(r.done[1].tasks[1]->ie, 2);
}

TEST(Dispatcher, WithoutBoundsOnlyCompiledTasks) {
    Recorder r;
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    Dispatcher d({unevaluated({})}, 1, false, false, r.callbacks);
    Job job = *d.next_job();
    EXPECT_EQ(job.kind, JobKind::EXPLICABILITY);
    d.finish_rest(); // out of time while the job is away: reported when it is back
    EXPECT_TRUE(r.done.empty());
    TaskExplicability limit; // LIMIT
    d.receive({job, std::nullopt, std::nullopt, limit});
    ASSERT_EQ(r.done.size(), 1u);
    EXPECT_EQ(r.done[0].status, EvaluationStatus::LIMIT);
}

// Tasks the search already knows (inherited from a smaller configuration) get no job, nor
// does a robot bound that is known; a configuration known in full is done at once.
TEST(Dispatcher, KnownTasksAndBoundsGetNoJob) {
    Recorder r;
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    TaskExplicability known;
    known.status = ExplicabilityStatus::SOLVED;
    known.ie = 1;
    ConfigurationEvaluation partial = unevaluated({0});
    partial.tasks = {known, std::nullopt, std::nullopt};
    partial.robot_cost_bounds = {std::nullopt, 4.0, std::nullopt};
    ConfigurationEvaluation full = unevaluated({1});
    full.tasks = {known, known, known};
    Dispatcher d({full, partial}, 3, true, false, r.callbacks);
    std::vector<Job> sent;
    while (auto job = d.next_job())
        sent.push_back(*job);
    ASSERT_EQ(r.done.size(), 1u); // {1}: everything was known
    EXPECT_EQ(r.done[0].configuration, Configuration{1});
    EXPECT_EQ(r.done[0].status, EvaluationStatus::COMPLETE);
    ASSERT_EQ(sent.size(), 1u); // only task 2's robot bound; then its tasks wait for it
    EXPECT_EQ(sent[0].kind, JobKind::ROBOT_BOUND);
    EXPECT_EQ(sent[0].task, 2);
    d.receive({sent[0], 5.0, std::nullopt, {}});
    sent.clear();
    while (auto job = d.next_job())
        sent.push_back(*job);
    ASSERT_EQ(sent.size(), 2u);
    EXPECT_EQ(sent[0].task, 1);
    EXPECT_EQ(sent[1].task, 2);
    for (const auto &job : sent) {
        EXPECT_EQ(job.kind, JobKind::EXPLICABILITY);
        d.receive({job, std::nullopt, std::nullopt, known});
    }
    ASSERT_EQ(r.done.size(), 2u);
    EXPECT_EQ(r.done[1].status, EvaluationStatus::COMPLETE);
    EXPECT_EQ(r.done[1].robot_cost_bounds[1], 4.0);
}

TEST(Dispatcher, AnIeFloorAbandonsBeforeTheOtherBounds) {
    Recorder r;
    r.callbacks.abandon = [](const ConfigurationEvaluation &e) {
        for (const auto &floor : e.ie_floors)
            if (floor.value_or(1) > 100)
                return true;
        return false;
    };
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    Dispatcher d({unevaluated({})}, 3, true, false, r.callbacks);
    Job first = *d.next_job(); // one worker: one job at a time
    EXPECT_EQ(first.kind, JobKind::ROBOT_BOUND);
    d.receive({first, 7.0, std::nullopt, {}}); // no floor: the next bound goes out
    Job second = *d.next_job();
    EXPECT_EQ(second.kind, JobKind::ROBOT_BOUND);
    EXPECT_EQ(second.task, 1);
    d.receive({second, 9.0, 403.0, {}}); // e^6: no need for the third bound
    ASSERT_EQ(r.done.size(), 1u);
    EXPECT_EQ(r.done[0].status, EvaluationStatus::CUT_OFF);
    EXPECT_EQ(r.done[0].ie_floors[1], 403.0);
    EXPECT_FALSE(r.done[0].ie_floors[0]);
    EXPECT_FALSE(d.next_job());
}

// With IE floors, a robot bound the search inherited (rising_bounds.h) still gets a job: it
// carries the bound, the answer keeps it and adds the floor. An infinite bound gets none.
TEST(Dispatcher, AGivenBoundTravelsWithItsFloorJob) {
    Recorder r;
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    ConfigurationEvaluation e = unevaluated({2});
    e.robot_cost_bounds = {22.0, INF};
    Dispatcher d({e}, 2, true, true, r.callbacks);
    Job job = *d.next_job();
    EXPECT_EQ(job.kind, JobKind::ROBOT_BOUND);
    EXPECT_EQ(job.task, 0);
    ASSERT_TRUE(job.robot_bound);
    EXPECT_EQ(*job.robot_bound, 22.0);
    EXPECT_FALSE(d.next_job()); // task 1's infinite bound needs no floor
    d.receive({job, std::nullopt, 54.6, {}});
    std::vector<Job> sent;
    while (auto next = d.next_job())
        sent.push_back(*next);
    ASSERT_EQ(sent.size(), 2u);
    for (const auto &j : sent)
        d.receive({j, std::nullopt, std::nullopt, solved(1)});
    ASSERT_EQ(r.done.size(), 1u);
    EXPECT_EQ(r.done[0].robot_cost_bounds[0], 22.0);
    EXPECT_EQ(r.done[0].ie_floors[0], 54.6);
}

// Exact bounds first (the explaining robot): a configuration that survives its given bounds
// asks each again without it before any task is evaluated, and the exact one (with its floor)
// may abandon it.
TEST(Dispatcher, ExactBoundsFirstReplaceGivenOnes) {
    Recorder r;
    double limit = 10;
    r.callbacks.abandon = [&](const ConfigurationEvaluation &p) {
        return p.robot_cost_bounds[0] && *p.robot_cost_bounds[0] > limit;
    };
    r.callbacks.done = [&](ConfigurationEvaluation e) { r.done.push_back(std::move(e)); };
    ConfigurationEvaluation e = unevaluated({1});
    e.robot_cost_bounds = {8.0};
    Dispatcher d({e}, 1, true, true, r.callbacks, true);
    Job floor_job = *d.next_job();
    ASSERT_TRUE(floor_job.robot_bound); // the floor first, with the bound given
    d.receive({floor_job, std::nullopt, 2.0, {}});
    Job exact = *d.next_job();
    EXPECT_EQ(exact.kind, JobKind::ROBOT_BOUND);
    EXPECT_FALSE(exact.robot_bound); // now c_R* itself
    EXPECT_FALSE(d.next_job());      // no task before it is back
    d.receive({exact, 12.0, 7.0, {}});
    ASSERT_EQ(r.done.size(), 1u);
    EXPECT_EQ(r.done[0].status, EvaluationStatus::CUT_OFF);
    EXPECT_EQ(r.done[0].robot_cost_bounds[0], 12.0);
    EXPECT_EQ(r.done[0].ie_floors[0], 7.0);

    // Without the option the task is evaluated on the given bound.
    r.done.clear();
    Dispatcher plain({e}, 1, true, true, r.callbacks);
    Job job = *plain.next_job();
    plain.receive({job, std::nullopt, 2.0, {}});
    EXPECT_EQ(plain.next_job()->kind, JobKind::EXPLICABILITY);
}

} // namespace
} // namespace envdesign::design
