#include "design/model/numbers.h"

#include <cmath>
#include <sstream>

namespace envdesign::design {

std::optional<std::string> number_problem(double value, NumberRange range) {
    if (std::isfinite(value) && value >= range.low && value <= range.high)
        return std::nullopt;
    std::ostringstream text;
    text << "must be a number in [" << range.low << ", " << range.high << "] (got " << value << ")";
    return text.str();
}

bool valid_plan_cost(double cost) { return cost == INF || !number_problem(cost, PLAN_COST); }

bool valid_ie(double ie) { return !std::isnan(ie) && ie >= 0; }

bool valid_explanation_floor(double told) {
    return !number_problem(told, EXPLANATION_FLOOR) && told == std::floor(told);
}

std::optional<std::string> evaluation_problem(const TaskExplicability &e) {
    if (e.status != ExplicabilityStatus::SOLVED && e.status != ExplicabilityStatus::INEXPLICABLE)
        return "the evaluation is neither solved nor inexplicable";
    if (!valid_plan_cost(e.robot_cost) || !valid_plan_cost(e.human_plan_cost) ||
        (e.human_optimal_cost && !valid_plan_cost(*e.human_optimal_cost)))
        return "a plan cost is not a cost in [0, 2^31) or infinite";
    if (e.explanation && !valid_plan_cost(e.explanation->robot_optimal_cost))
        return "the explanation's robot cost is not a cost in [0, 2^31) or infinite";
    if (!valid_ie(e.ie))
        return "the IE is not a number >= 0";
    if (e.status == ExplicabilityStatus::INEXPLICABLE && e.ie != INF)
        return "an inexplicable evaluation with a finite IE";
    if (e.status == ExplicabilityStatus::SOLVED && e.robot_cost == INF)
        return "a solved evaluation without a robot cost";
    return std::nullopt;
}

} // namespace envdesign::design
