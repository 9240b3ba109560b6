#pragma once
// Design problems as design requests (--redesign coordinator): a spec file with its PDDL
// files inlined (spec_t, as envdesign-coordinator loads it), and the same spec with a new
// task distribution and new tasks.

#include "arrivals/distribution.h"
#include "arrivals/tracker.h"
#include "envdesign/spec_t.hpp"

#include <string>
#include <vector>

namespace envdesign::bridge {

// Reads the spec file and every file it names. Throws pddl::ParseError
// ("FILE:LINE:COL: error: ...") for a spec that does not parse or a file it cannot read.
envdesign::spec_t read_spec_message(const std::string &spec_path);

// `spec` with each task's probability set from `d` (a task `d` leaves out: 0) and
// `new_tasks` appended, their problems inlined as "new-tasks/task-I.pddl" (and
// "new-tasks/task-I-human.pddl"), I the task's index. Throws pddl::ParseError if the spec text does
// not parse.
envdesign::spec_t with_distribution(const envdesign::spec_t &spec, const arrivals::Distribution &d,
                                    const std::vector<arrivals::NewTask> &new_tasks);

} // namespace envdesign::bridge
