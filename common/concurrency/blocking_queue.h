#pragma once
// The one blocking queue (issue 23): threads hand one another jobs, answers or arrivals
// through it, first in first out. Unbounded; every member is thread-safe.
//
//   BlockingQueue<Job> jobs;
//   jobs.push(job);                                    // any thread
//   while (auto job = jobs.pop()) run(*job);           // a worker, until close()
//   auto answer = answers.pop_until(deadline);         // nullopt: deadline, wake() or close()
//   jobs.replace_or_push(job, same_problem);           // a newer job takes an older one's turn
//   jobs.remove_if(withdrawn);
//   jobs.close();                                      // waiters return; the rest drains
//
// wake() makes one wait return early, or the next one if none waits: a wait that returns
// uses up the wake, whatever it returns. pop() is a wait too, so a `while (auto job =
// jobs.pop())` worker ends on a wake(): wake only queues whose waiters expect it. A closed queue
// still takes pushes (a worker that drains it may queue follow-up work) unless it was closed with
// Leftovers::drop.

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

namespace envdesign::concurrency {

// What close() does with the items still queued.
enum class Leftovers {
    drain, // pops return them, then nullopt
    drop,  // they are gone, and so is every later push: pops return nullopt at once
};

template <class T> class BlockingQueue {
public:
    void push(T item) {
        {
            std::lock_guard lock(mutex_);
            if (dropping_)
                return;
            items_.push_back(std::move(item));
        }
        changed_.notify_one();
    }

    // Puts `item` in place of the first queued item `same` holds for (it keeps that one's
    // turn), else at the back; true when it replaced one.
    template <class Same> bool replace_or_push(T item, Same same) {
        bool replaced = false;
        {
            std::lock_guard lock(mutex_);
            if (dropping_)
                return false;
            auto queued = std::find_if(items_.begin(), items_.end(), same);
            replaced = queued != items_.end();
            if (replaced)
                *queued = std::move(item);
            else
                items_.push_back(std::move(item));
        }
        changed_.notify_one();
        return replaced;
    }

    // Takes back the queued items `pred` holds for; returns how many.
    template <class Pred> std::size_t remove_if(Pred pred) {
        std::lock_guard lock(mutex_);
        return std::erase_if(items_, pred);
    }

    // Blocks until an item is there, wake() or close(); the first item, else nullopt.
    std::optional<T> pop() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return ready(); });
        return front_after_wait();
    }

    // As pop(), but nullopt too once `deadline` passed.
    template <class Clock, class Duration>
    std::optional<T> pop_until(const std::chrono::time_point<Clock, Duration> &deadline) {
        std::unique_lock lock(mutex_);
        changed_.wait_until(lock, deadline, [&] { return ready(); });
        return front_after_wait();
    }

    template <class Rep, class Period>
    std::optional<T> pop_for(const std::chrono::duration<Rep, Period> &timeout) {
        std::unique_lock lock(mutex_);
        changed_.wait_for(lock, timeout, [&] { return ready(); });
        return front_after_wait();
    }

    // Blocks as pop_for() does but takes nothing; true when items are waiting.
    template <class Rep, class Period>
    bool wait_for(const std::chrono::duration<Rep, Period> &timeout) {
        std::unique_lock lock(mutex_);
        changed_.wait_for(lock, timeout, [&] { return ready(); });
        woken_ = false;
        return !items_.empty();
    }

    // Moves up to `max` items, oldest first, to the back of `out` without waiting; returns
    // how many.
    std::size_t take(std::vector<T> &out, std::size_t max) {
        std::lock_guard lock(mutex_);
        std::size_t n = 0;
        for (; n < max && !items_.empty(); ++n) {
            out.push_back(std::move(items_.front()));
            items_.pop_front();
        }
        return n;
    }

    void wake() {
        {
            std::lock_guard lock(mutex_);
            woken_ = true;
        }
        changed_.notify_all(); // the first waiter to run uses it up; the others wait on
    }

    // Every wait returns, now and from now on, once nothing is left to pop.
    void close(Leftovers leftovers = Leftovers::drain) {
        {
            std::lock_guard lock(mutex_);
            closed_ = true;
            if (leftovers == Leftovers::drop) {
                dropping_ = true;
                items_.clear();
            }
        }
        changed_.notify_all();
    }

    std::size_t size() const {
        std::lock_guard lock(mutex_);
        return items_.size();
    }

private:
    bool ready() const { return woken_ || closed_ || !items_.empty(); }

    // Under the lock, after a wait, which used up any wake().
    std::optional<T> front_after_wait() {
        woken_ = false;
        if (items_.empty())
            return std::nullopt;
        std::optional<T> item(std::move(items_.front()));
        items_.pop_front();
        return item;
    }

    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<T> items_;
    bool woken_ = false;
    bool closed_ = false;
    bool dropping_ = false; // closed with Leftovers::drop
};

} // namespace envdesign::concurrency
