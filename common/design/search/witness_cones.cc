#include "design/search/witness_cones.h"

#include "design/behaviour/behaviour.h"

#include <algorithm>
#include <iterator>

namespace envdesign::design::witness {

Cone cone_of(const DesignProblem &problem, const SupersetBound &bound, const Configuration &design,
             const std::vector<Record> &records) {
    if (!behaviour_of(problem.weights.behaviour).value_follows_witnesses)
        return Cone{design, std::nullopt}; // no lemma there: the design alone
    Cone cone{design, std::vector<int>{}};
    for (std::size_t t = 0; t < records.size() && cone.escapes; ++t) {
        if (problem.tasks[t].probability <= 0)
            continue;
        if (!records[t] || !records[t]->touch.known) {
            cone.escapes.reset();
            break;
        }
        std::vector<int> both;
        std::set_union(cone.escapes->begin(), cone.escapes->end(), records[t]->touch.all.begin(),
                       records[t]->touch.all.end(), std::back_inserter(both));
        cone.escapes = std::move(both);
    }
    for (int m : bound.always()) // not restricting or of negative cost: never in a cone
        if (cone.escapes && !contains(*cone.escapes, m))
            cone.escapes->insert(std::upper_bound(cone.escapes->begin(), cone.escapes->end(), m),
                                 m);
    return cone;
}

void offer_cone_of(const DesignProblem &problem, const SupersetBound &bound,
                   const Configuration &design, const std::vector<Record> &records, int max_size,
                   Ranking &ranking) {
    Cone cone = cone_of(problem, bound, design, records);
    if (!cone.escapes)
        return;
    std::vector<const TaskExplicability *> tasks;
    for (const Record &r : records) {
        if (!r)
            return;
        tasks.push_back(&r->evaluation);
    }
    std::vector<int> free;
    for (int m = 0; m < static_cast<int>(problem.modifications.size()); ++m)
        if (!contains(design, m) && !contains(*cone.escapes, m))
            free.push_back(m);
    offer_cone(problem, design, tasks, free, max_size, ranking);
}

} // namespace envdesign::design::witness
