#pragma once
// Content addresses of lifted models (a domain and a problem). Equal addresses mean the
// grounder gets the same input, hence the same ground task and the same planner answer, so
// a model that no modification of a configuration touched need not be ground again
// (plan_cache.h, solve_model). Everything the grounder reads is hashed: types, constants,
// predicates, functions, action schemas with their costs, objects, init, function values,
// goal and metric; names of files and source locations are not.

#include "design/model/ground_key.h"
#include "pddl/task.h"

namespace envdesign::design {

TaskKey lifted_key(const pddl::Domain &domain, const pddl::Problem &problem);
// The canonical text lifted_key hashes (evaluation_store.h names durable records by a
// SHA-256 of it).
std::string lifted_text(const pddl::Domain &domain, const pddl::Problem &problem);

} // namespace envdesign::design
