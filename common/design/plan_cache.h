#pragma once
// The design engine's planner: optimal plans of ground tasks, each distinct task solved once.
//
// solve() canonicalizes the task (ground_key.h), looks its key up and plans only on a miss.
// Calls are thread-safe: while one thread plans a task, another asking for an equal task
// waits for that answer instead of planning it again (it counts as a cache hit). Answers cut
// short by the time limit are not kept.
//
// Example:
//   PlanCache cache(planning::PlannerOptions{});
//   PlanOutcome p = cache.solve(ground::ground(domain, problem), Deadline{});
//   if (p.status == PlanStatus::SOLVED) ... p.cost, p.secondary_cost, p.plan ...

#include "design/deadline.h"
#include "design/ground_key.h"
#include "planning/planner.h"

#include <atomic>
#include <future>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace envdesign::design {

enum class PlanStatus { SOLVED, UNSOLVABLE, LIMIT };

struct PlanOutcome {
    PlanStatus status = PlanStatus::LIMIT;
    long long cost = 0;            // primary cost of the plan
    long long secondary_cost = 0;  // sum of the operators' secondary costs
    std::vector<std::string> plan;
};

struct CacheCounters {
    long long planner_runs = 0;  // searches actually run
    long long cache_hits = 0;    // answers taken from an equal task
    double planner_seconds = 0;  // time spent in those searches, summed over threads
};

class PlanCache {
public:
    explicit PlanCache(planning::PlannerOptions options) : options_(std::move(options)) {}

    // An optimal plan of `task` (primary cost, then secondary cost), or a proof that there
    // is none, or LIMIT when `deadline` passed first.
    PlanOutcome solve(const ground::GroundTask &task, const Deadline &deadline);

    CacheCounters counters() const;

private:
    PlanOutcome run_planner(const ground::GroundTask &canonical, const Deadline &deadline);

    planning::PlannerOptions options_;
    mutable std::mutex mutex_;
    std::map<TaskKey, std::shared_future<PlanOutcome>> answers_;
    CacheCounters counters_;
};

}  // namespace envdesign::design
