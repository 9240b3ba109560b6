#pragma once
// The warnings of `envdesign design`: on stderr as "warning: ..." lines and in the JSON
// result as "warnings": [...]. A spec the reader accepted but may not mean (probabilities not
// summing to 1, two problems of a task with different goals: DesignProblem::warnings), and tasks
// that are unsolvable in the unmodified models, each with the reason (so that `objective: inf`
// comes with a word why).

#include "design/deadline.h"
#include "design/design_search.h"
#include "design/plan_cache.h"

#include <string>
#include <vector>

namespace envdesign::cli {

// One line per task of result.baseline with infinite IE, naming it and why; plans P_R (and
// P_H when not known) through `planner` until `deadline`.
std::vector<std::string> unsolvable_task_warnings(const design::DesignProblem &problem,
                                                  const design::DesignResult &result,
                                                  design::PlanCache &planner,
                                                  const design::Deadline &deadline);

// With --connect: the loader's warnings of the spec file read here (parsed only: the
// coordinator checks it again and reports bad input; a spec that does not read gives none).
std::vector<std::string> remote_spec_warnings(const std::string &spec_path);

// With --connect: the unsolvable-task lines of `result_json` (the coordinator's result, whose
// explanation has each task's baseline): tasks with infinite IE there are planned here, from
// the spec file read here, for the reason, as in-process. None if the spec does not read.
std::vector<std::string> remote_unsolvable_task_warnings(const std::string &spec_path,
                                                         const std::string &result_json,
                                                         const design::Deadline &deadline);

// `json_text` (a JSON result object) with "warnings": `warnings` when there are any.
std::string with_warnings(const std::string &json_text, const std::vector<std::string> &warnings);

// Prints each on stderr, prefixed "warning: " unless it already names its place.
void print_warnings(const std::vector<std::string> &warnings);

} // namespace envdesign::cli
