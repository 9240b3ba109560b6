#pragma once
// What the tests hear on LCM: the bridge's estimates and requests, every design result and
// the last status of each service, collected by a bus thread of the test's own.

#include "bus/bus.h"
#include "bus/channels.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/service_status_t.hpp"
#include "envdesign/task_distribution_t.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace envdesign::testing {

class Listener {
public:
    using Clock = std::chrono::steady_clock;
    template <typename T> struct Heard {
        T message;
        Clock::time_point at;
    };

    explicit Listener(const std::string &url) : bus_(url, nullptr) {
        subscriptions_.push_back(bus_.subscribe<envdesign::task_distribution_t>(
            "ENVDESIGN_TASK_DISTRIBUTION",
            [this](const envdesign::task_distribution_t &m) { add(distributions_, m); }));
        subscriptions_.push_back(bus_.subscribe<envdesign::task_distribution_t>(
            "ENVDESIGN_REEVALUATE",
            [this](const envdesign::task_distribution_t &m) { add(requests_, m); }));
        subscriptions_.push_back(bus_.subscribe<envdesign::design_result_t>(
            bus::RESULT, [this](const envdesign::design_result_t &m) { add(results_, m); }));
        subscriptions_.push_back(bus_.subscribe<envdesign::service_status_t>(
            bus::STATUS, [this](const envdesign::service_status_t &m) {
                {
                    std::lock_guard lock(mutex_);
                    statuses_[m.sender] = m;
                }
                changed_.notify_all();
            }));
        thread_ = std::thread([this] {
            while (!stop_)
                bus_.handle(std::chrono::milliseconds(20));
        });
    }
    ~Listener() {
        stop_ = true;
        thread_.join();
    }

    // Waits until `done` holds (checked on every message and every 50 ms); false on timeout.
    bool wait_until(const std::function<bool()> &done, std::chrono::milliseconds timeout) {
        auto until = Clock::now() + timeout;
        while (!done()) {
            if (Clock::now() >= until)
                return false;
            std::unique_lock lock(mutex_);
            changed_.wait_for(lock, std::chrono::milliseconds(50));
        }
        return true;
    }

    std::vector<Heard<envdesign::task_distribution_t>> distributions() {
        return copy(distributions_);
    }
    std::vector<Heard<envdesign::task_distribution_t>> requests() { return copy(requests_); }
    std::vector<Heard<envdesign::design_result_t>> results() { return copy(results_); }

    // The last estimate of `problem`, if any.
    std::optional<envdesign::task_distribution_t> last_estimate(const std::string &problem) {
        std::lock_guard lock(mutex_);
        for (auto it = distributions_.rbegin(); it != distributions_.rend(); ++it)
            if (it->message.problem_id == problem)
                return it->message;
        return std::nullopt;
    }

    // The last status of the service named `sender` (--name), if heard.
    std::optional<envdesign::service_status_t> status(const std::string &sender) {
        std::lock_guard lock(mutex_);
        auto it = statuses_.find(sender);
        return it == statuses_.end() ? std::nullopt : std::optional(it->second);
    }
    // A drop counter (channel, reason) of that status; -1 if it has none.
    long long status_drops(const std::string &sender, const std::string &channel,
                           const std::string &reason) {
        auto s = status(sender);
        for (int i = 0; s && i < s->num_drops; ++i)
            if (s->drop_channels[i] == channel && s->drop_reasons[i] == reason)
                return s->drop_counts[i];
        return -1;
    }

    bus::Bus &bus() { return bus_; }

private:
    template <typename T> void add(std::vector<Heard<T>> &to, const T &m) {
        {
            std::lock_guard lock(mutex_);
            to.push_back({m, Clock::now()});
        }
        changed_.notify_all();
    }
    template <typename T> std::vector<T> copy(const std::vector<T> &from) {
        std::lock_guard lock(mutex_);
        return from;
    }

    bus::Bus bus_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<Heard<envdesign::task_distribution_t>> distributions_, requests_;
    std::vector<Heard<envdesign::design_result_t>> results_;
    std::map<std::string, envdesign::service_status_t> statuses_;
    std::vector<bus::Subscription> subscriptions_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

} // namespace envdesign::testing
