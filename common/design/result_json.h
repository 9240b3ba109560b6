#pragma once
// The JSON results of SPEC.md: `envdesign explicable --json` and `envdesign design --json`.
// Infinite numbers are the string "inf"; numbers not known (not computed) are null.

#include "design/design_search.h"
#include "design/explicability.h"

#include <nlohmann/json.hpp>

namespace envdesign::design {

// `value` as one line of text. Names come from input files byte for byte; bytes that are not
// UTF-8 become U+FFFD here instead of making nlohmann's dump() throw after the work is done.
std::string json_text(const nlohmann::json &value);

// A finite number, "inf", or null when unset.
nlohmann::json json_number(std::optional<double> value);

// {"status", "plan", "ie", "robot_cost", "human_plan_cost", "human_optimal_cost"}
nlohmann::json explicability_json(const TaskExplicability &result);

// {"status", "design", "objective", "terms", "baseline", "tasks",
//  "configurations_evaluated", "planner_runs", "seconds", ...statistics}
nlohmann::json design_json(const DesignProblem &problem, const DesignResult &result);

} // namespace envdesign::design
