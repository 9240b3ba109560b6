#include "design/evaluation/plan_cache.h"

#include "ground/stop.h"

#include <algorithm>
#include <chrono>

namespace envdesign::design {

PlanOutcome PlanCache::solve(const ground::GroundTask &task, const Deadline &deadline,
                             PlanChoice choice) {
    ground::GroundTask canonical = canonicalize(task);
    return memoized(answers_, {key_of(canonical), choice}, false,
                    [&] { return run_planner(canonical, deadline, choice); });
}

PlanOutcome PlanCache::solve_model(const TaskKey &lifted,
                                   const std::function<ground::GroundTask()> &ground,
                                   const Deadline &deadline, PlanChoice choice) {
    return memoized(model_answers_, {lifted, choice}, true, [&] {
        try {
            return solve(ground(), deadline, choice);
        } catch (const ground::GroundingStopped &) {
            return PlanOutcome{}; // LIMIT, and not kept
        }
    });
}

PlanOutcome PlanCache::memoized(Answers &answers, const Key &key, bool lifted,
                                const std::function<PlanOutcome()> &compute) {
    std::promise<PlanOutcome> promise;
    std::shared_future<PlanOutcome> answer;
    bool owner = false;
    {
        std::lock_guard lock(mutex_);
        auto it = answers.find(key);
        if (it != answers.end()) {
            ++counters_.cache_hits;
            counters_.groundings_skipped += lifted ? 1 : 0;
            answer = it->second;
        } else {
            counters_.planner_runs += lifted ? 0 : 1;
            answer = promise.get_future().share();
            answers.emplace(key, answer);
            owner = true;
        }
    }
    if (!owner)
        return answer.get(); // blocks while another thread computes the same answer
    PlanOutcome outcome;
    try {
        outcome = compute();
    } catch (...) {
        promise.set_exception(std::current_exception());
        std::lock_guard lock(mutex_);
        answers.erase(key);
        throw;
    }
    promise.set_value(outcome);
    if (outcome.status == PlanStatus::LIMIT) {
        std::lock_guard lock(mutex_);
        answers.erase(key);
    }
    return outcome;
}

void PlanCache::remember_cheaper_plan(const std::vector<std::string> &robot_plan,
                                      const std::vector<std::string> &plan) {
    std::lock_guard lock(mutex_);
    if (cheaper_plans_kept_ >= kMaxCheaperPlans)
        return;
    auto &kept = cheaper_plans_[robot_plan];
    if (std::find(kept.begin(), kept.end(), plan) != kept.end())
        return;
    kept.push_back(plan);
    ++cheaper_plans_kept_;
}

std::vector<std::vector<std::string>>
PlanCache::cheaper_plans(const std::vector<std::string> &robot_plan) const {
    std::lock_guard lock(mutex_);
    auto it = cheaper_plans_.find(robot_plan);
    return it == cheaper_plans_.end() ? std::vector<std::vector<std::string>>{} : it->second;
}

CacheCounters PlanCache::counters() const {
    std::lock_guard lock(mutex_);
    return counters_;
}

PlanOutcome PlanCache::run_planner(const ground::GroundTask &canonical, const Deadline &deadline,
                                   PlanChoice choice) {
    auto start = std::chrono::steady_clock::now();
    planning::PlannerOptions options = options_;
    options.inherit_cuts = choice == PlanChoice::ANY_OPTIMAL;
    if (deadline.stop_flag())
        options.limits.stop = deadline.stop_flag();
    if (deadline.limited()) {
        double left = deadline.remaining_seconds();
        options.limits.time_limit_s =
            options.limits.time_limit_s > 0 ? std::min(options.limits.time_limit_s, left) : left;
    }
    planning::PlanReport report = planning::plan_task(canonical, options);
    PlanOutcome outcome;
    if (report.status == search::SearchStatus::SOLVED) {
        outcome.status = PlanStatus::SOLVED;
        outcome.cost = report.cost;
        outcome.plan = report.plan;
        // Canonical operators are sorted by name, and a ground action's name is unique.
        for (const auto &step : report.plan) {
            auto it = std::lower_bound(
                canonical.operators.begin(), canonical.operators.end(), step,
                [](const auto &op, const std::string &name) { return op.name < name; });
            outcome.secondary_cost += it->secondary_cost;
        }
    } else {
        outcome.status = report.status == search::SearchStatus::FAILED ? PlanStatus::UNSOLVABLE
                                                                       : PlanStatus::LIMIT;
    }
    std::lock_guard lock(mutex_);
    counters_.planner_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
}

} // namespace envdesign::design
