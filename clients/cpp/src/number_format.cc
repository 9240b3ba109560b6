#include "result_format.h"

#include "design/objective/formula.h"

#include <cmath>
#include <cstdio>

namespace envdesign::client {

nlohmann::json json_number(std::optional<double> value) {
    if (!value || std::isnan(*value))
        return nullptr;
    if (std::isinf(*value))
        return *value > 0 ? "inf" : "-inf";
    if (*value == std::floor(*value) && std::abs(*value) < 1e15)
        return static_cast<long long>(*value);
    return *value;
}

std::string json_text(const nlohmann::json &value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string shown(double value) {
    if (std::isnan(value))
        return "?";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[64];
    if (value == std::floor(value) && std::abs(value) < 1e15)
        std::snprintf(buffer, sizeof buffer, "%lld", static_cast<long long>(value));
    else if (std::abs(value) >= 1000 && std::abs(value) < 1e9)
        std::snprintf(buffer, sizeof buffer, "%.1f", value);
    else
        std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

double objective_with(const envdesign::explanation_t &w, const envdesign::design_point_t &point,
                      int horizon, double alpha) {
    if (std::isnan(point.expected_ie))
        return NAN;
    if (std::isinf(point.expected_ie))
        return INFINITY;
    namespace formula = design::formula; // the searches' own arithmetic
    return formula::weighted_sum(alpha, w.beta, w.kappa,
                                 point.expected_ie * formula::discounted_horizon(w.gamma, horizon),
                                 point.design_cost, horizon * point.expected_robot_cost, 0);
}

std::string plan_name(const std::string &robot_behaviour) {
    if (robot_behaviour == "COST_OPTIMAL")
        return "the worst of the robot's optimal plans";
    if (robot_behaviour == "COST_OPTIMAL_BEST_CASE")
        return "the best of the robot's optimal plans";
    if (robot_behaviour == "EXPLAINING")
        return "the plan the robot follows";
    return "the most explicable plan";
}

std::string design_set(const std::vector<std::string> &design) {
    if (design.empty())
        return "{} (the empty design)";
    std::string out = "{";
    for (std::size_t i = 0; i < design.size(); ++i)
        out += (i ? ", " : "") + design[i];
    return out + "}";
}

} // namespace envdesign::client
