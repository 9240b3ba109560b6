#pragma once
// robot_behaviour EXPLAINING on the wire (wire.h's hooks): a task's explaining option
// (TaskExplanation <-> explanation_t) and, in a result, the option the robot takes.

#include "design/design_problem.h"
#include "design/task_evaluation.h"
#include "envdesign/explanation_t.hpp"
#include "envdesign/task_result_t.hpp"

#include <optional>
#include <string>

namespace envdesign::cluster {

envdesign::explanation_t explanation_message(const design::TaskExplanation &x);
design::TaskExplanation explanation_value(const envdesign::explanation_t &m);

// Why `m` cannot be an explanation (a cost that is not a non-negative number).
std::optional<std::string> explanation_problem(const envdesign::explanation_t &m);

// In EXPLAINING mode with an explanation: the option taken (explaining.h) in `m`'s ie,
// robot_cost, plan and its explanation fields; otherwise nothing changes.
void put_option(const design::ObjectiveWeights &weights, const design::TaskExplicability &t,
                envdesign::task_result_t &m);

} // namespace envdesign::cluster
