#pragma once
// The design engine's planner: optimal plans of ground tasks, each distinct task solved once.
//
// solve() canonicalizes the task (ground_key.h), looks its key up and plans only on a miss.
// solve_model() goes one step earlier: keyed by the lifted model (lifted_key.h), it does not
// even ground a model it has seen (most modifications leave one of the two models alone).
// Calls are thread-safe: while one thread plans a task, another asking for an equal task
// waits for that answer instead of planning it again (it counts as a cache hit). Answers cut
// short by the time limit are not kept.
//
// Example:
//   PlanCache cache(planning::PlannerOptions{});
//   PlanOutcome p = cache.solve(ground::ground(domain, problem), Deadline{});
//   if (p.status == PlanStatus::SOLVED) ... p.cost, p.secondary_cost, p.plan ...

#include "design/model/ground_key.h"
#include "design/search/deadline.h"
#include "planning/planner.h"

#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::design {

enum class PlanStatus { SOLVED, UNSOLVABLE, LIMIT };

// Which optimal plan a caller needs. ANY_OPTIMAL: the one the fastest search finds (A* with
// LM-cut estimates inherited along the path, search/inherited_lmcut.h), the same for a task
// whoever asks: for answers that are costs, or any optimal plan. PLANNERS: the one the
// planner finds (`envdesign plan`, LM-cut in every state), where the plan itself decides a
// value: the explaining robot explains its optimal plan, and another one may need another
// explanation. Both are kept apart, so each asks its own search whatever ran before.
enum class PlanChoice { ANY_OPTIMAL, PLANNERS };

struct PlanOutcome {
    PlanStatus status = PlanStatus::LIMIT;
    long long cost = 0;           // primary cost of the plan
    long long secondary_cost = 0; // sum of the operators' secondary costs
    std::vector<std::string> plan;
};

struct CacheCounters {
    long long planner_runs = 0;       // searches actually run
    long long cache_hits = 0;         // answers taken from an equal task (or an equal lifted model)
    long long groundings_skipped = 0; // of those, found by the lifted model
    double planner_seconds = 0;       // time spent in those searches, summed over threads
};

class PlanCache {
public:
    explicit PlanCache(planning::PlannerOptions options) : options_(std::move(options)) {}

    // An optimal plan of `task` (primary cost, then secondary cost), or a proof that there
    // is none, or LIMIT when `deadline` passed first.
    PlanOutcome solve(const ground::GroundTask &task, const Deadline &deadline,
                      PlanChoice choice = PlanChoice::ANY_OPTIMAL);

    // The answer for a lifted model whose content address is `lifted`; calls `ground` and
    // solve() only when no model with that address was seen.
    PlanOutcome solve_model(const TaskKey &lifted,
                            const std::function<ground::GroundTask()> &ground,
                            const Deadline &deadline, PlanChoice choice = PlanChoice::ANY_OPTIMAL);

    CacheCounters counters() const;
    const planning::PlannerOptions &options() const { return options_; }

    // Plans of a human model cheaper than the robot's plan `robot_plan` there, met by
    // explanation searches (explanation_hitting.h). Another design that keeps such a plan
    // needs an explanation that breaks it, so its search starts from them instead of planning
    // them again. Bounded: once kMaxCheaperPlans are kept, later ones are not.
    void remember_cheaper_plan(const std::vector<std::string> &robot_plan,
                               const std::vector<std::string> &plan);
    std::vector<std::vector<std::string>>
    cheaper_plans(const std::vector<std::string> &robot_plan) const;
    static constexpr int kMaxCheaperPlans = 4096;

private:
    using Key = std::pair<TaskKey, PlanChoice>;
    using Answers = std::map<Key, std::shared_future<PlanOutcome>>;

    // The answer under `key` in `answers`, computed by `compute` on a miss; `lifted` says
    // which counters a hit and a miss move.
    PlanOutcome memoized(Answers &answers, const Key &key, bool lifted,
                         const std::function<PlanOutcome()> &compute);
    PlanOutcome run_planner(const ground::GroundTask &canonical, const Deadline &deadline,
                            PlanChoice choice);

    planning::PlannerOptions options_;
    mutable std::mutex mutex_;
    Answers answers_;       // by ground task and choice
    Answers model_answers_; // by lifted model and choice
    CacheCounters counters_;
    std::map<std::vector<std::string>, std::vector<std::vector<std::string>>> cheaper_plans_;
    int cheaper_plans_kept_ = 0;
};

} // namespace envdesign::design
