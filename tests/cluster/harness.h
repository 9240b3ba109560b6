#pragma once
// A coordinator and planners in this process on one memq:// bus, run by one loop thread,
// and the reference answer of a local (in-process evaluator) run to compare with.

#include "bus/bus.h"
#include "bus/channels.h"
#include "cluster/coordinator.h"
#include "cluster/planner.h"
#include "design/design_explanation.h"
#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "result_format.h"
#include "spec/design_spec.h"
#include "spec/spec_bundle.h"
#include "wire/result_message.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <condition_variable>
#include <filesystem>
#include <functional>
#include <map>
#include <thread>

namespace envdesign::cluster::testing {

inline std::shared_ptr<spdlog::logger> quiet_logger() {
    auto log =
        std::make_shared<spdlog::logger>("test", std::make_shared<spdlog::sinks::null_sink_mt>());
    return log;
}

inline std::string in_repo(const std::string &relative) {
    return std::string(ENVDESIGN_TEST_DATA_ROOT) + "/" + relative;
}

// SPEC.md's JSON of a run with the in-process evaluator (what `envdesign design --json`
// prints), the reference a networked run must equal.
inline nlohmann::json local_result(const std::string &spec_path) {
    design::DesignProblem problem = spec::load_design_problem(spec_path);
    design::LocalEvaluator evaluator(problem, 2);
    design::EvaluationLog log(problem, evaluator);
    design::RunSettings settings;
    settings.time_limit_s = 0; // none: the reference is the proven answer
    return client::result_json_value(wire::result_message(
        problem, design::run_design(problem, log, &evaluator.planner(), settings)));
}

// The fields of SPEC.md's result that do not depend on how the work was spread (the witness
// search's counts depend on the order answers come back in, its answer does not).
inline void expect_same_design(const nlohmann::json &got, const nlohmann::json &want) {
    for (const char *key :
         {"status", "design", "objective", "terms", "baseline", "tasks", "limit_reached"})
        EXPECT_EQ(got.at(key), want.at(key)) << key;
    // The explanation travels in design_result_t: the same per-task comparison, plans and
    // marginal values (break-even's set of evaluated designs depends on the work's order).
    for (const char *key : {"weighted_terms", "least_inexplicability", "weights"})
        EXPECT_EQ(got.value(key, nlohmann::json()), want.value(key, nlohmann::json())) << key;
    if (want.contains("explanation")) {
        for (const char *key : {"tasks", "marginal"})
            EXPECT_EQ(got.at("explanation").at(key), want.at("explanation").at(key)) << key;
    }
}

inline envdesign::design_request_t request_of(const std::string &spec_path, std::int64_t id) {
    envdesign::design_request_t r{};
    r.utime = 1;
    r.request_id = id;
    r.sender = "test-client";
    r.spec = spec::bundle_spec(spec_path);
    r.time_limit_s = -1;
    r.max_design_size = -1;
    return r;
}

class MemqCluster {
public:
    // `planners` planner cores with `workers` each; `setup` may add more on the bus (before
    // the loop starts) and returns a tick for them; `configure` changes the coordinator's
    // configuration.
    MemqCluster(int planners, int workers = 1,
                std::function<std::function<void()>(bus::Bus &)> setup = {},
                std::function<void(CoordinatorConfig &)> configure = {})
        : bus_("memq://", quiet_logger()) {
        CoordinatorConfig c;
        c.instance = "coordinator";
        c.pool.planner_timeout_s = 0.5;
        c.pool.lost_after_s = 0.15;
        if (configure)
            configure(c);
        coordinator_ = std::make_unique<Coordinator>(bus_, c);
        for (int i = 0; i < planners; ++i) {
            PlannerConfig p;
            p.instance = "planner-" + std::to_string(i);
            p.workers = workers;
            p.heartbeat_period_s = 0.05;
            planners_.push_back(std::make_unique<Planner>(bus_, p));
        }
        if (setup)
            extra_tick_ = setup(bus_);
        results_ = bus_.subscribe<envdesign::design_result_t>(
            bus::RESULT, [this](const envdesign::design_result_t &r) {
                std::lock_guard lock(mutex_);
                got_[r.request_id] = r;
                ready_.notify_all();
            });
        loop_ = std::thread([this] { run(); });
    }

    ~MemqCluster() {
        stop_ = true;
        loop_.join();
    }

    bus::Bus &bus() { return bus_; }
    Coordinator &coordinator() { return *coordinator_; }

    // Publishes `r` and waits for its result.
    envdesign::design_result_t request(const envdesign::design_request_t &r,
                                       double timeout_s = 60) {
        bus_.publish(bus::REQUEST, r);
        return wait(r.request_id, timeout_s);
    }

    // Whether a result for `id` came.
    bool answered(std::int64_t id) {
        std::lock_guard lock(mutex_);
        return got_.count(id) > 0;
    }

    envdesign::design_result_t wait(std::int64_t id, double timeout_s = 60) {
        std::unique_lock lock(mutex_);
        bool ok = ready_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                                  [&] { return got_.count(id) > 0; });
        EXPECT_TRUE(ok) << "no result for request " << id;
        return ok ? got_.at(id) : envdesign::design_result_t{};
    }

private:
    void run() {
        while (!stop_) {
            bus_.handle(std::chrono::milliseconds(5));
            coordinator_->tick();
            for (auto &p : planners_)
                p->tick();
            if (extra_tick_)
                extra_tick_();
        }
    }

    bus::Bus bus_;
    std::unique_ptr<Coordinator> coordinator_;
    std::vector<std::unique_ptr<Planner>> planners_;
    std::function<void()> extra_tick_;
    bus::Subscription results_;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::map<std::int64_t, envdesign::design_result_t> got_;
    std::atomic<bool> stop_{false};
    std::thread loop_;
};

} // namespace envdesign::cluster::testing
