#pragma once
// The reference the searches are checked against: every configuration evaluated in full,
// with no bound, and the one that ranks first.

#include "design/evaluation/local_evaluator.h"
#include "design/model/configuration.h"
#include "design/objective/objective.h"

namespace envdesign::design::testing {

// `explained` counts the tasks whose chosen option was to explain (EXPLAINING).
inline RankedDesign every_configuration(const DesignProblem &p, int &explained) {
    LocalEvaluator evaluator(p, 1);
    int n = static_cast<int>(p.modifications.size());
    RankedDesign best;
    bool first = true;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
        Configuration c;
        for (int i = 0; i < n; ++i)
            if (mask & (1u << i))
                c.push_back(i);
        std::vector<TaskExplicability> tasks;
        for (std::size_t t = 0; t < p.tasks.size(); ++t) {
            tasks.push_back(evaluator.evaluate_task(c, static_cast<int>(t), Deadline{}));
            explained += choose_behaviour(p.weights, tasks.back()).explained;
        }
        double cost = design_cost(p, c);
        RankedDesign r{objective_of(p, cost, tasks).value, cost, c};
        if (first || ranks_before(r, best))
            best = r;
        first = false;
    }
    return best;
}

} // namespace envdesign::design::testing
