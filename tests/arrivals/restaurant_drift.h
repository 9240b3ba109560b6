#pragma once
// What several arrivals tests share, defined once: a unity batch compiles them as one file,
// where a helper each file defined for itself would clash.

#include "arrivals/distribution.h"
#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"

#include "spec/design_spec.h"

#include <cstdint>
#include <string>

namespace envdesign::arrivals {

// The tests' wall clock: 2023-11-14, microseconds since the Unix epoch.
inline constexpr std::int64_t NOW_UTIME = 1'700'000'000'000'000;

// The restaurant whose task mix drifts (tests/arrivals/data).
inline const std::string RESTAURANT_DRIFT =
    std::string(ENVDESIGN_ARRIVALS_DATA) + "/restaurant-drift.textproto";

// Its task distribution with `p` for serve-g1 and the rest for serve-g2.
inline Distribution g1(double p) { return {{"serve-g1", p}, {"serve-g2", 1 - p}}; }

// A fresh search (new evaluator, empty caches) of RESTAURANT_DRIFT with D = `d`.
inline design::DesignResult fresh(const Distribution &d) {
    design::DesignProblem problem = spec::load_design_problem(RESTAURANT_DRIFT);
    for (auto &t : problem.tasks)
        t.probability = d.at(t.name);
    design::LocalEvaluator evaluator(problem, 1);
    return design::search_design(problem, evaluator, {});
}

} // namespace envdesign::arrivals
