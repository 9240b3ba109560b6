#pragma once
// One design request on the coordinator: its own thread loads the spec (the same checks as
// a local run), hands the spec to the planners (spec_library.h), runs the design search
// (design_search.h) over an LcmEvaluator and keeps the result. The coordinator's bus
// thread reads progress() and result() and publishes them.

#include "bus/bus.h"
#include "cluster/evaluation_stores.h"
#include "cluster/job_router.h"
#include "cluster/spec_library.h"
#include "design/design_problem.h"
#include "design/design_run.h"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace envdesign::cluster {

class LcmEvaluator;

// What a run uses of its coordinator; all must outlive the run.
struct RunContext {
    bus::Bus &bus;
    JobRouter &router;
    SpecLibrary &specs;
    double grace_s = 1.0; // after the deadline, planners' LIMIT answers are awaited this long
    EvaluationStores *stores = nullptr; // evaluations kept across requests; null: none
    double max_time_limit_s = 0;        // the coordinator's cap on a request's time; 0: none
    std::string client; // the request's unit of fair shares (Coordinator::client_unit)
};

class RequestRun {
public:
    RequestRun(RunContext context, envdesign::design_request_t request);
    ~RequestRun(); // cancels and joins
    RequestRun(const RequestRun &) = delete;
    RequestRun &operator=(const RequestRun &) = delete;

    void start();
    // Stops the search soon; the result is what was found (exit code 4, limit_reached).
    void cancel();
    bool finished() const { return finished_.load(); }

    const std::string &name() const { return name_; } // "client#id"
    const envdesign::design_request_t &request() const { return request_; }
    // Request fields, state and counters filled; the caller adds utime, sender, planners.
    envdesign::design_progress_t progress() const;
    // Once finished(): the result, header fields left to the caller.
    envdesign::design_result_t result() const;

private:
    void run();
    void search(const design::DesignProblem &problem, const std::string &hash);
    design::RunSettings settings() const; // the request's overrides of its spec's
    void set_state(std::int8_t state);
    void finish(envdesign::design_result_t result);

    RunContext context_;
    envdesign::design_request_t request_;
    std::string name_;
    std::chrono::steady_clock::time_point accepted_ = std::chrono::steady_clock::now();
    std::atomic<bool> cancelled_{false};
    std::atomic<bool> finished_{false};
    mutable std::mutex mutex_;
    envdesign::design_progress_t progress_{};
    envdesign::design_result_t result_{};
    LcmEvaluator *evaluator_ = nullptr; // while searching
    std::thread thread_;
};

} // namespace envdesign::cluster
