// A planner's memory of answers by content (answer_memory.h).

#include "cluster/answer_memory.h"

#include <gtest/gtest.h>

namespace envdesign::cluster {
namespace {

envdesign::job_t job(std::int64_t id, const std::string &coordinator, std::vector<int> mods,
                     int task = 0) {
    envdesign::job_t j{};
    j.job_id = id;
    j.request_id = id * 10;
    j.sender = coordinator;
    j.spec_hash = std::string(64, 'a');
    j.kind = envdesign::job_t::KIND_EXPLICABILITY;
    j.task = static_cast<std::int16_t>(task);
    for (int m : mods)
        j.modifications.push_back(static_cast<std::int16_t>(m));
    j.num_modifications = static_cast<std::int16_t>(j.modifications.size());
    return j;
}

envdesign::evaluation_t answer(std::int8_t status, double ie) {
    envdesign::evaluation_t a{};
    a.status = status;
    a.ie = ie;
    a.planner_runs = 2;
    a.seconds = 0.5;
    return a;
}

TEST(AnswerMemory, ContentIsWhatIsAskedNotWhoAsks) {
    EXPECT_EQ(job_content(job(1, "a", {0, 2})), job_content(job(99, "b", {0, 2})));
    EXPECT_NE(job_content(job(1, "a", {0, 2})), job_content(job(1, "a", {0, 3})));
    EXPECT_NE(job_content(job(1, "a", {0, 2})), job_content(job(1, "a", {0, 2}, 1)));
    EXPECT_NE(job_content(job(1, "a", {1, 2})), job_content(job(1, "a", {12})));
    auto bound = job(1, "a", {0, 2});
    bound.kind = envdesign::job_t::KIND_ROBOT_BOUND;
    EXPECT_NE(job_content(bound), job_content(job(1, "a", {0, 2})));
    auto hmax = job(1, "a", {0, 2});
    hmax.heuristic = 1;
    EXPECT_NE(job_content(hmax), job_content(job(1, "a", {0, 2})));
}

TEST(AnswerMemory, AnswersAnotherCoordinatorsJobAsItsOwn) {
    AnswerMemory memory(10);
    memory.keep(job_content(job(1, "old", {1})), answer(envdesign::evaluation_t::STATUS_SOLVED, 3));
    auto asked = job(7, "new", {1});
    auto kept = memory.find(job_content(asked));
    ASSERT_TRUE(kept);
    auto out = readdressed(*kept, asked, "planner-0");
    EXPECT_EQ(out.job_id, 7);
    EXPECT_EQ(out.request_id, 70);
    EXPECT_EQ(out.coordinator, "new");
    EXPECT_EQ(out.sender, "planner-0");
    EXPECT_EQ(out.ie, 3);
    EXPECT_EQ(out.planner_runs, 0); // no planner work for this job
}

TEST(AnswerMemory, KeepsOnlyAnswersThatDoNotDependOnTime) {
    AnswerMemory memory(10);
    memory.keep("limit", answer(envdesign::evaluation_t::STATUS_LIMIT, 0));
    memory.keep("error", answer(envdesign::evaluation_t::STATUS_ERROR, 0));
    memory.keep("none", answer(envdesign::evaluation_t::STATUS_INEXPLICABLE, 1e300));
    EXPECT_FALSE(memory.find("limit"));
    EXPECT_FALSE(memory.find("error"));
    EXPECT_TRUE(memory.find("none"));
}

TEST(AnswerMemory, ForgetsTheLeastRecentlyUsedPastItsCapacity) {
    AnswerMemory memory(3);
    for (const char *c : {"a", "b", "c"})
        memory.keep(c, answer(envdesign::evaluation_t::STATUS_SOLVED, 1));
    EXPECT_TRUE(memory.find("a")); // a is now the most recent
    memory.keep("d", answer(envdesign::evaluation_t::STATUS_SOLVED, 1));
    EXPECT_EQ(memory.size(), 3u);
    EXPECT_TRUE(memory.find("a"));
    EXPECT_FALSE(memory.find("b"));
    EXPECT_TRUE(memory.find("d"));
}

} // namespace
} // namespace envdesign::cluster
