#pragma once
// robot_behaviour EXPLAINING on the wire (wire.h's hooks): a task's explaining option
// (TaskExplanation <-> model_explanation_t) and, in a result, the option the robot takes.

#include "design/design_problem.h"
#include "design/evaluation/task_evaluation.h"
#include "envdesign/model_explanation_t.hpp"
#include "envdesign/task_result_t.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace envdesign::wire {

// The fields task_result_t and evaluation_t share.
template <typename Message>
void put_costs_and_plan(const design::TaskExplicability &t, Message &m) {
    m.ie = t.ie;
    m.robot_cost = t.robot_cost;
    m.human_plan_cost = t.human_plan_cost;
    m.has_human_optimal_cost = t.human_optimal_cost.has_value();
    m.human_optimal_cost = t.human_optimal_cost.value_or(design::INF);
    m.plan = t.plan;
    m.plan_length = static_cast<std::int16_t>(m.plan.size());
}

envdesign::model_explanation_t model_explanation_message(const design::TaskExplanation &x);
design::TaskExplanation model_explanation_value(const envdesign::model_explanation_t &m);

// In EXPLAINING mode with an explanation: the option taken (explaining.h) in `m`'s ie,
// robot_cost, plan and its explanation fields; otherwise nothing changes.
void put_option(const design::ObjectiveWeights &weights, const design::TaskExplicability &t,
                envdesign::task_result_t &m);

} // namespace envdesign::wire
