#pragma once
// robot_behaviour EXPLAINING on the wire (wire.h's hooks): a task's explaining option
// (TaskExplanation <-> model_explanation_t) and, in a result, the option the robot takes.

#include "design/design_problem.h"
#include "design/evaluation/task_evaluation.h"
#include "envdesign/model_explanation_t.hpp"
#include "envdesign/task_result_t.hpp"

#include <optional>
#include <string>

namespace envdesign::wire {

envdesign::model_explanation_t model_explanation_message(const design::TaskExplanation &x);
design::TaskExplanation model_explanation_value(const envdesign::model_explanation_t &m);

// In EXPLAINING mode with an explanation: the option taken (explaining.h) in `m`'s ie,
// robot_cost, plan and its explanation fields; otherwise nothing changes.
void put_option(const design::ObjectiveWeights &weights, const design::TaskExplicability &t,
                envdesign::task_result_t &m);

} // namespace envdesign::wire
