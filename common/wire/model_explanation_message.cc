#include "wire/model_explanation_message.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/explaining.h"

#include <cmath>

namespace envdesign::wire {

envdesign::model_explanation_t model_explanation_message(const design::TaskExplanation &x) {
    envdesign::model_explanation_t m;
    m.found = x.found;
    m.robot_optimal_cost = x.robot_optimal_cost;
    m.robot_plan = x.robot_plan;
    m.robot_plan_length = static_cast<std::int16_t>(m.robot_plan.size());
    m.differences = x.differences;
    m.differences_length = static_cast<std::int16_t>(m.differences.size());
    return m;
}

design::TaskExplanation model_explanation_value(const envdesign::model_explanation_t &m) {
    return {m.found != 0, m.robot_optimal_cost, m.robot_plan, m.differences};
}

void put_option(const design::ObjectiveWeights &weights, const design::TaskExplicability &t,
                envdesign::task_result_t &m) {
    m.has_explanation =
        design::behaviour_of(weights.behaviour).may_explain && t.explanation.has_value();
    m.explained = false;
    m.explicable_ie = t.ie;
    if (!m.has_explanation) {
        m.explanation = model_explanation_message({});
        return;
    }
    m.explanation = model_explanation_message(*t.explanation);
    design::BehaviourChoice c = design::choose_behaviour(weights, t);
    m.explained = c.explained;
    if (c.explained) {
        m.ie = c.ie;
        m.robot_cost = c.robot_cost;
        m.plan = t.explanation->robot_plan;
        m.plan_length = static_cast<std::int16_t>(m.plan.size());
    }
}

} // namespace envdesign::wire
