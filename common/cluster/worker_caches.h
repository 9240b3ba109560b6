#pragma once
// A planner worker's evaluators (planner.h), one per (spec, heuristic), each with its own
// plan cache, so that a job's counters are its own; a new evaluator's search gets the
// memory the process leaves of the job limit (planner_memory.h).

#include "cluster/planner_memory.h"
#include "cluster/planner_specs.h"
#include "design/evaluation/local_evaluator.h"
#include "wire/job_messages.h"

#include <map>
#include <memory>
#include <string>

namespace envdesign::cluster {

// One worker's evaluators, one per (spec, heuristic), each with its own plan cache.
class WorkerCaches {
public:
    WorkerCaches(int max_specs, std::size_t memory_bytes, int workers)
        : max_(max_specs), memory_bytes_(memory_bytes), workers_(workers) {}

    design::LocalEvaluator &get(const std::shared_ptr<const LoadedSpec> &spec,
                                std::int8_t heuristic) {
        std::string key = spec->hash + "/" + std::to_string(heuristic);
        auto it = entries_.find(key);
        if (it == entries_.end()) {
            if (static_cast<int>(entries_.size()) >= max_)
                entries_.clear(); // rare: more specs in use than kept; start over
            planning::PlannerOptions options;
            options.heuristic = wire::heuristic_kind(heuristic);
            // The search's share of the limit is what the process leaves of it now (code,
            // specs, caches; other workers' searches): the planner's size holds the limit.
            options.limits.memory_limit_bytes =
                job_search_budget(memory_bytes_, resident_bytes(), workers_);
            Entry entry{spec, std::make_unique<design::LocalEvaluator>(*spec->problem, 1, options)};
            it = entries_.emplace(key, std::move(entry)).first;
        }
        return *it->second.evaluator;
    }

private:
    struct Entry {
        std::shared_ptr<const LoadedSpec> spec; // keeps the problem alive
        std::unique_ptr<design::LocalEvaluator> evaluator;
    };
    int max_;
    std::size_t memory_bytes_;
    int workers_;
    std::map<std::string, Entry> entries_;
};

} // namespace envdesign::cluster
