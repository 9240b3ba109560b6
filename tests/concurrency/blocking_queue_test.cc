// The one blocking queue (common/concurrency/blocking_queue.h) between real threads.
#include "concurrency/blocking_queue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace envdesign::concurrency {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Long enough that a waiter is asleep in the queue before the main thread acts.
constexpr milliseconds SETTLE{50};
// A wait that must not run out during the test.
constexpr std::chrono::seconds LONG_WAIT{30};

TEST(BlockingQueue, PopUntilTimesOutWithNothingQueued) {
    BlockingQueue<int> queue;
    auto start = Clock::now();
    EXPECT_EQ(queue.pop_until(start + milliseconds(60)), std::nullopt);
    EXPECT_GE(Clock::now() - start, milliseconds(60));
    EXPECT_EQ(queue.pop_for(milliseconds(10)), std::nullopt);
    EXPECT_FALSE(queue.wait_for(std::chrono::duration<double>(0.01)));
}

TEST(BlockingQueue, PushFromAnotherThreadEndsTheWait) {
    BlockingQueue<std::string> queue;
    auto popped = std::async(std::launch::async, [&] { return queue.pop_for(LONG_WAIT); });
    std::this_thread::sleep_for(SETTLE);
    queue.push("job");
    ASSERT_EQ(popped.wait_for(LONG_WAIT), std::future_status::ready);
    EXPECT_EQ(popped.get(), "job");
}

TEST(BlockingQueue, WakeReturnsOneWaiterEarly) {
    BlockingQueue<int> queue;
    auto start = Clock::now();
    auto popped =
        std::async(std::launch::async, [&] { return queue.pop_until(start + LONG_WAIT); });
    std::this_thread::sleep_for(SETTLE);
    queue.wake();
    ASSERT_EQ(popped.wait_for(LONG_WAIT), std::future_status::ready);
    EXPECT_EQ(popped.get(), std::nullopt);
    EXPECT_LT(Clock::now() - start, LONG_WAIT / 2);
    // The waiter used the wake up: the next wait runs to its deadline.
    EXPECT_EQ(queue.pop_for(milliseconds(20)), std::nullopt);
    EXPECT_GE(Clock::now() - start, SETTLE + milliseconds(20));
}

TEST(BlockingQueue, WakeWithNoWaiterEndsTheNextWaitOnly) {
    BlockingQueue<int> queue;
    queue.wake();
    auto start = Clock::now();
    EXPECT_FALSE(queue.wait_for(LONG_WAIT));
    EXPECT_LT(Clock::now() - start, LONG_WAIT / 2);
    EXPECT_FALSE(queue.wait_for(milliseconds(20)));
    EXPECT_GE(Clock::now() - start, milliseconds(20));
    queue.push(7);
    queue.wake(); // an item there: the wait says so, and the wake is used up with it
    EXPECT_TRUE(queue.wait_for(LONG_WAIT));
    EXPECT_EQ(queue.pop_for(milliseconds(1)), 7);
}

TEST(BlockingQueue, CloseReleasesEveryWaiterAndThenDrains) {
    BlockingQueue<int> queue;
    std::vector<std::future<std::optional<int>>> waiters;
    for (int i = 0; i < 3; ++i)
        waiters.push_back(std::async(std::launch::async, [&] { return queue.pop(); }));
    std::this_thread::sleep_for(SETTLE);
    queue.close();
    for (auto &waiter : waiters) {
        ASSERT_EQ(waiter.wait_for(LONG_WAIT), std::future_status::ready);
        EXPECT_EQ(waiter.get(), std::nullopt);
    }
    // Closed, it still takes pushes (a draining worker may queue follow-up work).
    queue.push(1);
    queue.push(2);
    EXPECT_EQ(queue.pop(), 1);
    EXPECT_EQ(queue.pop_until(Clock::now() + LONG_WAIT), 2);
    EXPECT_EQ(queue.pop(), std::nullopt);
    EXPECT_FALSE(queue.wait_for(LONG_WAIT));
}

TEST(BlockingQueue, CloseDroppingForgetsQueuedAndLaterItems) {
    BlockingQueue<int> queue;
    queue.push(1);
    queue.close(Leftovers::drop);
    EXPECT_EQ(queue.pop(), std::nullopt);
    queue.push(2);
    EXPECT_FALSE(queue.replace_or_push(3, [](int) { return true; }));
    EXPECT_EQ(queue.size(), 0u);
    EXPECT_EQ(queue.pop(), std::nullopt);
}

TEST(BlockingQueue, TakeMovesUpToMaxOldestFirst) {
    BlockingQueue<int> queue;
    for (int i = 1; i <= 5; ++i)
        queue.push(i);
    std::vector<int> out{0};
    EXPECT_EQ(queue.take(out, 3), 3u);
    EXPECT_EQ(out, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(queue.take(out, 10), 2u);
    EXPECT_EQ(out, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(queue.take(out, 10), 0u);
}

TEST(BlockingQueue, ItemsFromOneProducerComeInOrder) {
    BlockingQueue<int> queue;
    constexpr int COUNT = 10'000;
    std::thread producer([&] {
        for (int i = 0; i < COUNT; ++i)
            queue.push(i);
    });
    std::vector<int> got;
    while (static_cast<int>(got.size()) < COUNT)
        if (queue.wait_for(LONG_WAIT))
            queue.take(got, 64);
    producer.join();
    for (int i = 0; i < COUNT; ++i)
        ASSERT_EQ(got[i], i);
}

using Keyed = std::pair<std::string, int>;

TEST(BlockingQueue, ReplaceOrPushKeepsTheReplacedItemsTurn) {
    BlockingQueue<Keyed> queue;
    queue.push({"a", 1});
    queue.push({"b", 1});
    queue.push({"c", 1});
    auto same_key = [](const std::string &key) {
        return [key](const Keyed &queued) { return queued.first == key; };
    };
    EXPECT_TRUE(queue.replace_or_push({"b", 2}, same_key("b")));
    EXPECT_FALSE(queue.replace_or_push({"d", 1}, same_key("d")));
    std::vector<Keyed> out;
    queue.take(out, 10);
    EXPECT_EQ(out, (std::vector<Keyed>{{"a", 1}, {"b", 2}, {"c", 1}, {"d", 1}}));
}

TEST(BlockingQueue, ReplaceOrPushEndsAWait) {
    BlockingQueue<Keyed> queue;
    auto popped = std::async(std::launch::async, [&] { return queue.pop(); });
    std::this_thread::sleep_for(SETTLE);
    queue.replace_or_push({"a", 1}, [](const Keyed &) { return true; });
    ASSERT_EQ(popped.wait_for(LONG_WAIT), std::future_status::ready);
    EXPECT_EQ(popped.get(), Keyed("a", 1));
}

TEST(BlockingQueue, RemoveIfTakesBackOnlyTheMatchingItems) {
    BlockingQueue<int> queue;
    for (int i = 1; i <= 6; ++i)
        queue.push(i);
    EXPECT_EQ(queue.remove_if([](int i) { return i % 2 == 0; }), 3u);
    EXPECT_EQ(queue.remove_if([](int i) { return i > 100; }), 0u);
    EXPECT_EQ(queue.size(), 3u);
    EXPECT_EQ(queue.pop(), 1);
    EXPECT_EQ(queue.pop(), 3);
    EXPECT_EQ(queue.pop(), 5);
}

TEST(BlockingQueue, WorkersDrainEveryJobOnce) {
    BlockingQueue<int> jobs;
    BlockingQueue<int> answers;
    std::vector<std::thread> workers;
    for (int w = 0; w < 4; ++w)
        workers.emplace_back([&] {
            while (auto job = jobs.pop())
                answers.push(*job * 2);
        });
    constexpr int COUNT = 1000;
    for (int i = 0; i < COUNT; ++i)
        jobs.push(i);
    jobs.close();
    for (auto &worker : workers)
        worker.join();
    std::vector<int> got;
    EXPECT_EQ(answers.take(got, 2 * COUNT), static_cast<std::size_t>(COUNT));
    std::sort(got.begin(), got.end());
    for (int i = 0; i < COUNT; ++i)
        ASSERT_EQ(got[i], 2 * i);
}

} // namespace
} // namespace envdesign::concurrency
