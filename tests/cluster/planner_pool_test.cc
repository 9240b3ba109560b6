// The coordinator's bookkeeping of planners and jobs: round robin over free slots, re-sends
// of lost jobs and of the jobs of a planner that went silent, first answers win.

#include "cluster/planner_pool.h"

#include "bus/bus.h"
#include "cluster/job_router.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <thread>

namespace envdesign::cluster {
namespace {

using Clock = PlannerPool::Clock;
using namespace std::chrono_literals;

envdesign::planner_heartbeat_t beat(const std::string &name, int capacity,
                                    std::vector<std::int64_t> jobs = {}) {
    envdesign::planner_heartbeat_t b{};
    b.sender = name;
    b.capacity = static_cast<std::int16_t>(capacity);
    b.period_ms = 200;
    b.jobs = std::move(jobs);
    b.num_jobs = static_cast<std::int16_t>(b.jobs.size());
    return b;
}

envdesign::job_t job(std::int64_t id) {
    envdesign::job_t j{};
    j.job_id = id;
    j.kind = envdesign::job_t::KIND_EXPLICABILITY;
    return j;
}

TEST(PlannerPool, RoundRobinOverFreeSlotsThenQueue) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    EXPECT_EQ(pool.capacity(), 2);
    auto first = pool.submit(1, job(1), now);
    auto second = pool.submit(1, job(2), now);
    ASSERT_EQ(first.size(), 1u);
    ASSERT_EQ(second.size(), 1u);
    EXPECT_NE(first[0].planner, second[0].planner);
    EXPECT_TRUE(pool.submit(1, job(3), now).empty()); // both busy: queued
    std::vector<envdesign::job_t> freed;
    ASSERT_TRUE(pool.answer(1, first[0].planner, freed, now));
    ASSERT_EQ(freed.size(), 1u);
    EXPECT_EQ(freed[0].job_id, 3);
    EXPECT_EQ(freed[0].planner, first[0].planner);
}

TEST(PlannerPool, FirstAnswerWinsDuplicatesAreCounted) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.submit(7, job(1), now);
    std::vector<envdesign::job_t> freed;
    EXPECT_TRUE(pool.answer(1, "a", freed, now));
    EXPECT_FALSE(pool.answer(1, "a", freed, now));
    EXPECT_FALSE(pool.answer(99, "a", freed, now)); // never sent
    EXPECT_EQ(pool.counters().duplicates, 2);
    EXPECT_EQ(pool.counters(7).duplicates, 1);
    EXPECT_EQ(pool.counters(7).answered_by, std::set<std::string>{"a"});
}

TEST(PlannerPool, JobMissingFromALaterHeartbeatIsResent) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    auto sent = pool.submit(1, job(5), now);
    ASSERT_EQ(sent.size(), 1u);
    std::string first = sent[0].planner;
    // Soon after sending, a heartbeat may not list the job yet: nothing happens.
    EXPECT_TRUE(pool.heartbeat(beat(first, 1), now + 100ms).empty());
    // Listed: the planner is on it.
    EXPECT_TRUE(pool.heartbeat(beat(first, 1, {5}), now + 400ms).empty());
    // Not listed well after sending: lost (or its answer was); sent again, to the other.
    auto resent = pool.heartbeat(beat(first, 1), now + 600ms);
    ASSERT_EQ(resent.size(), 1u);
    EXPECT_EQ(resent[0].job_id, 5);
    EXPECT_EQ(resent[0].attempt, 1);
    EXPECT_NE(resent[0].planner, first);
    EXPECT_EQ(pool.counters(1).jobs_resent, 1);
}

TEST(PlannerPool, SilentPlannerIsDroppedAndItsJobsMove) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    auto sent = pool.submit(1, job(5), now);
    std::string silent = sent[0].planner, alive = silent == "a" ? "b" : "a";
    pool.heartbeat(beat(alive, 1), now + 900ms);
    auto moved = pool.expire(now + 1100ms);
    ASSERT_EQ(moved.size(), 1u);
    EXPECT_EQ(moved[0].planner, alive);
    EXPECT_EQ(pool.live_planners(), 1);
    // The lost planner's late answer still counts (first answer), the re-sent one does not.
    std::vector<envdesign::job_t> freed;
    EXPECT_TRUE(pool.answer(5, silent, freed, now + 1200ms));
    EXPECT_FALSE(pool.answer(5, alive, freed, now + 1300ms));
}

TEST(PlannerPool, StoppingPlannerIsDroppedAtOnce) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 2), now);
    pool.submit(1, job(1), now);
    auto stop = beat("a", 2);
    stop.stopping = true;
    EXPECT_TRUE(pool.heartbeat(stop, now).empty()); // nobody to take it: queued
    EXPECT_EQ(pool.live_planners(), 0);
    auto sent = pool.heartbeat(beat("b", 1), now);
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].planner, "b");
}

TEST(PlannerPool, SlotsPerWorkerPipelineJobs) {
    PlannerPool pool({1.0, 0.3, 2});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    EXPECT_EQ(pool.capacity(), 2);
    EXPECT_EQ(pool.submit(1, job(1), now).size(), 1u);
    EXPECT_EQ(pool.submit(1, job(2), now).size(), 1u); // queued at the planner
    EXPECT_TRUE(pool.submit(1, job(3), now).empty());
}

// A forgotten job its planner holds is withdrawn (a dropped request's never-ending search
// would go on for no one); its slot frees when the planner no longer lists it.
TEST(PlannerPool, ForgottenJobsAreWithdrawnAndFreeTheirSlots) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.submit(3, job(1), now);
    pool.submit(3, job(2), now);
    EXPECT_EQ(pool.jobs_in_flight(3), 2);
    pool.forget_owner(3);
    EXPECT_EQ(pool.jobs_in_flight(3), 0);
    auto withdrawn = pool.take_withdrawals();
    ASSERT_EQ(withdrawn.size(), 1u) << "job 2 was only queued";
    EXPECT_EQ(withdrawn[0].job_id, 1);
    EXPECT_TRUE(pool.submit(4, job(9), now).empty()) << "the planner still runs job 1";
    auto sent = pool.heartbeat(beat("a", 1), now); // job 1 no longer listed
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, 9);
}

TEST(PlannerPool, AnAnswerCountsOnlyFromAPlannerTheJobWasSentTo) {
    PlannerPool pool({1.0, 0.3, 1});
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    auto sent = pool.submit(1, job(1), now);
    std::string other = sent[0].planner == "a" ? "b" : "a";
    EXPECT_TRUE(pool.sent_to(1, sent[0].planner));
    EXPECT_FALSE(pool.sent_to(1, other));
    EXPECT_FALSE(pool.sent_to(1, "rogue"));
    EXPECT_TRUE(pool.sent_to(2, "rogue")) << "not outstanding: a duplicate, ignored anyway";
}

// A planner that lists its jobs and never answers (the fake planner) loses them at
// their deadline, keeps its slots taken while it lists them, and is demoted.
TEST(PlannerPool, JobsPastTheirDeadlineMoveAndTheirHolderIsDemoted) {
    PoolConfig config{10.0, 0.3, 1};
    config.job_deadline_s = 1.0;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 2), now);
    pool.heartbeat(beat("b", 1), now);
    EXPECT_EQ(pool.submit(1, job(1), now)[0].planner, "a");
    EXPECT_EQ(pool.submit(1, job(2), now)[0].planner, "b");
    EXPECT_EQ(pool.submit(1, job(3), now)[0].planner, "a");
    std::vector<envdesign::job_t> sent;
    EXPECT_TRUE(pool.answer(2, "b", sent, now + 100ms)); // fast: the deadline stays 1 s
    EXPECT_TRUE(sent.empty());
    pool.heartbeat(beat("a", 2, {1, 3}), now + 500ms);
    pool.heartbeat(beat("b", 1), now + 500ms);
    PlannerPool::Events events;
    pool.heartbeat(beat("a", 2, {1, 3}), now + 1100ms);
    sent = pool.expire(now + 1100ms, &events);
    ASSERT_EQ(sent.size(), 1u) << "b's one slot takes one; a's stay taken";
    EXPECT_EQ(sent[0].planner, "b");
    EXPECT_EQ(sent[0].attempt, 1);
    EXPECT_TRUE(pool.demoted("a"));
    EXPECT_EQ(pool.counters().deadlines_missed, 2);
    EXPECT_EQ(pool.counters().planners_demoted, 1);
    EXPECT_NE(std::find_if(events.begin(), events.end(),
                           [](const std::string &e) {
                               return e.find("planner a missed 2 job deadlines in a row: "
                                             "demoted") != std::string::npos;
                           }),
              events.end());
    // The fake keeps listing them: its slots stay taken, the other job waits for b.
    EXPECT_TRUE(pool.heartbeat(beat("a", 2, {1, 3}), now + 1200ms).empty());
    std::int64_t at_b = sent[0].job_id, waiting = at_b == 1 ? 3 : 1;
    sent.clear();
    EXPECT_TRUE(pool.answer(at_b, "b", sent, now + 1300ms));
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, waiting);
    EXPECT_EQ(sent[0].planner, "b");
    // b is busy and a lets go of its jobs: a demoted planner still works when no one else can.
    auto to_a = pool.submit(1, job(4), now + 1400ms);
    EXPECT_TRUE(to_a.empty());
    to_a = pool.heartbeat(beat("a", 2), now + 1400ms);
    ASSERT_EQ(to_a.size(), 1u);
    EXPECT_EQ(to_a[0].planner, "a");
    // An answer in time clears the demotion.
    EXPECT_TRUE(pool.answer(4, "a", sent, now + 1500ms));
    EXPECT_FALSE(pool.demoted("a"));
}

TEST(PlannerPool, LateAnswersCountAndStretchTheDeadline) {
    PoolConfig config{10.0, 0.3, 1};
    config.job_deadline_s = 1.0;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    std::string first = pool.submit(1, job(1), now)[0].planner;
    auto moved = pool.expire(now + 1100ms);
    ASSERT_EQ(moved.size(), 1u);
    EXPECT_NE(moved[0].planner, first);
    std::vector<envdesign::job_t> sent;
    EXPECT_TRUE(pool.answer(1, first, sent, now + 2s)) << "slow, not wrong: the first answer";
    EXPECT_DOUBLE_EQ(pool.deadline_s(), 8.0) << "4 x the 2 s it took";
    EXPECT_FALSE(pool.demoted(first)) << "one miss only";
    EXPECT_EQ(pool.capacity(), 2);
    EXPECT_EQ(pool.submit(1, job(2), now + 2s).size(), 1u) << "its slot is free again";
}

envdesign::planner_heartbeat_t working(const std::string &name, int capacity,
                                       std::vector<std::int64_t> jobs, double busy_seconds) {
    auto b = beat(name, capacity, std::move(jobs));
    b.busy_seconds = busy_seconds;
    return b;
}

// Issue 21: forty requests that never end held every slot. A request with a job waiting and
// no slot gets one: the youngest job past its quantum of the request holding the most is
// withdrawn; its slot frees when its planner lets go of it.
TEST(PlannerPool, ARequestHoldingNoSlotGetsOneByAWithdrawal) {
    PoolConfig config{10.0, 0.3, 1};
    config.job_deadline_s = 100;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    ASSERT_EQ(pool.submit(1, job(1), now).size(), 1u);
    EXPECT_TRUE(pool.submit(2, job(2), now + 1s).empty()) << "within job 1's quantum";
    EXPECT_TRUE(pool.take_withdrawals().empty());
    EXPECT_TRUE(pool.heartbeat(working("a", 1, {1}, 3), now + 3s).empty());
    auto withdrawn = pool.take_withdrawals();
    ASSERT_EQ(withdrawn.size(), 1u);
    EXPECT_EQ(withdrawn[0].job_id, 1);
    EXPECT_EQ(withdrawn[0].planner, "a");
    EXPECT_EQ(pool.counters().withdrawn, 1);
    EXPECT_TRUE(pool.heartbeat(working("a", 1, {1}, 3.1), now + 3100ms).empty())
        << "still listed: the slot is not free yet";
    auto sent = pool.heartbeat(working("a", 1, {}, 3.2), now + 3200ms);
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, 2) << "the request that had none goes first";
    std::vector<envdesign::job_t> next;
    ASSERT_TRUE(pool.answer(2, "a", next, now + 3300ms));
    EXPECT_TRUE(next.empty()) << "the slot waits anticipate_s for request 2's next job";
    next = pool.expire(now + 3300ms + 40ms);
    EXPECT_TRUE(next.empty());
    next = pool.expire(now + 3300ms + 60ms);
    ASSERT_EQ(next.size(), 1u);
    EXPECT_EQ(next[0].job_id, 1) << "then the withdrawn job again";
    EXPECT_TRUE(pool.take_withdrawals().empty());
}

// While clients contend, a search's next job (sent a moment after its last answer) finds
// the slot its answer freed, without withdrawing another client's job again.
TEST(PlannerPool, AnAnsweredSlotWaitsForItsClientsNextJob) {
    PoolConfig config{10.0, 0.3, 1};
    config.job_deadline_s = 100;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    ASSERT_EQ(pool.submit(1, job(1), now).size(), 1u);
    EXPECT_TRUE(pool.submit(2, job(2), now).empty());
    std::vector<envdesign::job_t> next;
    ASSERT_TRUE(pool.answer(1, "a", next, now + 10ms));
    EXPECT_TRUE(next.empty()) << "kept for request 1";
    auto sent = pool.submit(1, job(3), now + 20ms);
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, 3);
    EXPECT_TRUE(pool.take_withdrawals().empty());
}

// Issue 21's flood on two planners: a client that has used nothing takes both, not only
// its share of one. Each planner's running flood job and the one queued behind it (two jobs
// per worker while no one else waits) are withdrawn, and the freed slots are the client's.
TEST(PlannerPool, AMuchLighterClientTakesEveryPlannerItAsksFor) {
    PoolConfig config{10.0, 0.3, 2};
    config.job_deadline_s = 100;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    for (std::int64_t id = 1; id <= 6; ++id)
        pool.submit(1, job(id), now);
    auto at = now + 5s; // jobs 1 and 3 at a, 2 and 4 at b (two per worker), 5 and 6 queued
    EXPECT_TRUE(pool.heartbeat(working("a", 1, {1, 3}, 5), at).empty());
    EXPECT_TRUE(pool.heartbeat(working("b", 1, {2, 4}, 5), at).empty());
    EXPECT_TRUE(pool.submit(2, job(7), at).empty());
    EXPECT_TRUE(pool.submit(2, job(8), at).empty());
    std::set<std::int64_t> withdrawn;
    for (const auto &w : pool.take_withdrawals())
        withdrawn.insert(w.job_id);
    EXPECT_EQ(withdrawn, (std::set<std::int64_t>{1, 2, 3, 4}));
    auto sent = pool.heartbeat(working("a", 1, {}, 5), at + 10ms);
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, 7);
    sent = pool.heartbeat(working("b", 1, {}, 5), at + 10ms);
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].job_id, 8);
    EXPECT_TRUE(pool.take_withdrawals().empty());
}

// A planner whose heartbeats show it working keeps a job past the job deadline: a long
// search is not run twice at once. Past the job's own time limit it is taken.
TEST(PlannerPool, AWorkingPlannerKeepsItsJobUntilItsTimeLimit) {
    PoolConfig config{100.0, 0.3, 1};
    config.job_deadline_s = 1.0;
    PlannerPool pool(config);
    auto now = Clock::now();
    pool.heartbeat(beat("a", 1), now);
    pool.heartbeat(beat("b", 1), now);
    envdesign::job_t long_job = job(1);
    long_job.time_limit_s = 10;
    std::string holder = pool.submit(1, long_job, now)[0].planner;
    std::string other = holder == "a" ? "b" : "a";
    for (int s = 1; s <= 12; ++s) {
        auto at = now + std::chrono::seconds(s);
        pool.heartbeat(working(holder, 1, {1}, s), at);
        pool.heartbeat(beat(other, 1), at);
        EXPECT_TRUE(pool.expire(at).empty()) << "at " << s << " s";
    }
    auto moved = pool.expire(now + 12500ms);
    ASSERT_EQ(moved.size(), 1u) << "past its 10 s limit and the 2 s grace";
    EXPECT_EQ(moved[0].planner, other);
}

// Issue 21: a heartbeat is numbers from the wire. One whose busy_seconds is NaN, infinite or
// negative, or whose period_ms is 0 or beyond an hour, is dropped and counted by the
// coordinator's router, never used: no planner joins by it, a known one keeps the capacity
// its good heartbeats gave, and its "working" state still follows its good heartbeats (a
// NaN busy time taken in made every later one look idle, and a long job was taken from
// its planner at the job deadline).
TEST(PlannerPool, HeartbeatsWithBadNumbersAreDroppedAndChangeNothing) {
    bus::Bus bus("memq://", std::make_shared<spdlog::logger>(
                                "pool-test", std::make_shared<spdlog::sinks::null_sink_mt>()));
    PoolConfig config;
    config.planner_timeout_s = 30;
    config.job_deadline_s = 0.05;
    JobRouter router(bus, config, "coordinator");
    router.on_heartbeat(beat("a", 1));
    router.on_heartbeat(beat("b", 1));
    ASSERT_EQ(router.pool().live_planners(), 2);
    ASSERT_EQ(router.pool().capacity(), 4); // 2 planners x 1 worker x 2 jobs per worker
    Inbox inbox;
    std::uint64_t owner = router.open(inbox);
    envdesign::job_t long_job = job(0);
    long_job.time_limit_s = 60;
    std::int64_t id = router.send(owner, long_job);
    ASSERT_EQ(router.pool().jobs_in_flight(), 1);
    std::string holder = router.pool().sent_to(id, "a") ? "a" : "b";
    std::string other = holder == "a" ? "b" : "a";
    router.on_heartbeat(working(holder, 1, {id}, 1));

    std::vector<envdesign::planner_heartbeat_t> bad;
    const double inf = std::numeric_limits<double>::infinity();
    for (double busy : {std::nan(""), inf, -inf, -1.0})
        for (const std::string &name : {holder, std::string("c")})
            bad.push_back(working(name, 8, {id}, busy));
    for (int period : {0, -200, 3'600'001, INT_MAX})
        for (const std::string &name : {holder, std::string("c")}) {
            bad.push_back(working(name, 8, {id}, 2));
            bad.back().period_ms = period;
        }
    long long malformed = bus.malformed();
    for (const auto &b : bad)
        router.on_heartbeat(b);
    EXPECT_EQ(bus.malformed() - malformed, static_cast<long long>(bad.size()));
    EXPECT_EQ(router.pool().live_planners(), 2) << "c never joined";
    EXPECT_EQ(router.pool().counters().planners_joined, 2);
    EXPECT_EQ(router.pool().capacity(), 4) << "not 8 workers from a dropped heartbeat";

    // A second on, the holder's busy time grows past its last good heartbeat's (1 s): it is
    // working, and keeps its job past the 0.05 s job deadline.
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    router.on_heartbeat(working(holder, 1, {id}, 2));
    router.on_heartbeat(beat(other, 1));
    router.tick();
    EXPECT_EQ(router.pool().counters().jobs_resent, 0) << "the job was taken from " << holder;
    EXPECT_TRUE(router.pool().sent_to(id, holder));
    EXPECT_FALSE(router.pool().sent_to(id, other));

    // The ends of the range are heartbeats like any other.
    auto slowest = beat("d", 1);
    slowest.period_ms = 3'600'000;
    auto fastest = working("e", 1, {}, 0);
    fastest.period_ms = 1;
    router.on_heartbeat(slowest);
    router.on_heartbeat(fastest);
    EXPECT_EQ(router.pool().live_planners(), 4);
    EXPECT_FALSE(heartbeat_problem(slowest));
    EXPECT_EQ(heartbeat_problem(working("f", 1, {}, std::nan(""))).value_or(""),
              "busy_seconds must be finite and at least 0 (got nan)");
    router.close(owner);
}

} // namespace
} // namespace envdesign::cluster
