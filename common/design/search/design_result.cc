#include "design/search/design_result.h"

#include <algorithm>
#include <climits>

namespace envdesign::design {

long long binomial(long long n, long long k) {
    if (k < 0 || k > n)
        return 0;
    k = std::min(k, n - k);
    long double value = 1;
    for (long long i = 1; i <= k; ++i)
        value = value * static_cast<long double>(n - k + i) / static_cast<long double>(i);
    return value >= static_cast<long double>(LLONG_MAX) ? LLONG_MAX
                                                        : static_cast<long long>(value + 0.5L);
}

double own_lower_bound(const DesignProblem &problem, double cost,
                       const ConfigurationEvaluation &partial) {
    std::vector<const TaskExplicability *> known;
    for (const auto &t : partial.tasks)
        known.push_back(t ? &*t : nullptr);
    return objective_lower_bound(problem, cost, known, partial.robot_cost_bounds, partial.ie_floors,
                                 partial.explanation_floors);
}

void close_counters(DesignCounters &counters, const Evaluator &evaluator,
                    std::chrono::steady_clock::time_point start) {
    counters.evaluator = evaluator.counters();
    counters.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void consider_design(const DesignProblem &problem, const Configuration &configuration,
                     std::vector<TaskExplicability> tasks, DesignResult &result, Ranking &ranking) {
    EvaluatedDesign design;
    double cost = design_cost(problem, configuration);
    design.tasks = std::move(tasks);
    design.objective = objective_of(problem, cost, design.tasks);
    design.ranked = {design.objective.value, cost, configuration};
    if (configuration.empty())
        result.baseline = design;
    ranking.offer(design.ranked);
    if (!result.best || ranks_before(design.ranked, result.best->ranked))
        result.best = std::move(design);
}

double ranking_limit(const DesignResult &result, const Ranking &ranking) {
    if (!result.best)
        return INF;
    return std::max(result.best->objective.value, ranking.threshold());
}

} // namespace envdesign::design
