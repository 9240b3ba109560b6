#pragma once
// Design problems as design requests (--redesign coordinator): a spec_t (packed by
// spec/spec_bundle.h) with a new task distribution and new tasks.

#include "arrivals/distribution.h"
#include "arrivals/tracker.h"
#include "envdesign/spec_t.hpp"

#include <string>
#include <vector>

namespace envdesign::bridge {

// `spec` with each task's probability set from `d` (a task `d` leaves out: 0) and
// `new_tasks` appended, their problems inlined as "new-tasks/task-I.pddl" (and
// "new-tasks/task-I-human.pddl"), I the task's index. Throws pddl::ParseError if the spec text does
// not parse.
envdesign::spec_t with_distribution(const envdesign::spec_t &spec, const arrivals::Distribution &d,
                                    const std::vector<arrivals::NewTask> &new_tasks);

} // namespace envdesign::bridge
