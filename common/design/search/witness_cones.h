#pragma once
// The cones of evaluated designs: the supersets that provably rank after a design, from the
// witnesses of its tasks (hitting_set.h excludes them; ranking.h lists their members).

#include "design/design_problem.h"
#include "design/search/hitting_set.h"
#include "design/search/ranking.h"
#include "design/search/witness_bound.h"

#include <vector>

namespace envdesign::design::witness {

// `design` and the supersets that provably rank after it (hitting_set.h), from the records
// of its tasks.
Cone cone_of(const DesignProblem &problem, const SupersetBound &bound, const Configuration &design,
             const std::vector<Record> &records);

// Offers `design` + E to `ranking` for every E in its cone (ranking.h's offer_cone): the
// members' tasks are those of `design`, so no planning. Nothing when a record is missing
// or a task's objective is infinite. `max_size`: the largest design (no 0).
void offer_cone_of(const DesignProblem &problem, const SupersetBound &bound,
                   const Configuration &design, const std::vector<Record> &records, int max_size,
                   Ranking &ranking);

} // namespace envdesign::design::witness
