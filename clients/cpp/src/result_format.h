#pragma once
// The one result formatter: design_result_t (the message ENVDESIGN_RESULT carries, which the
// local CLI builds too, wire/result_message.h) -> what `envdesign design` and `evaluate`
// print, as SPEC.md's JSON (full precision) or as text (rounded for reading), and the
// report's HTML (report_html.h). docs/result.md explains every field.

#include "envdesign/design_result_t.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace envdesign::client {

// A finite number (integral values as integers), "inf", or null when unset or NaN.
nlohmann::json json_number(std::optional<double> value);
// `value` as one line. Names come from input files byte for byte; bytes that are not UTF-8
// become U+FFFD instead of making nlohmann's dump() throw after the work is done.
std::string json_text(const nlohmann::json &value);
// A number for people: integers as such, else 4 significant digits (1 decimal from 1000 on),
// "inf" for infinity, "?" when not known.
std::string shown(double value);

nlohmann::json result_json_value(const envdesign::design_result_t &result);
std::string result_json(const envdesign::design_result_t &result);
std::string result_text(const envdesign::design_result_t &result);

// Objective of a design point under the result's weights with another horizon or alpha
// (the report's plots); NaN when the point's expectations are not known.
double objective_with(const envdesign::explanation_t &weights,
                      const envdesign::design_point_t &point, int horizon, double alpha);

// What a task's plan pi is under the result's robot_behaviour (explanation_t): "the most
// explicable plan" (the paper), "the worst of the robot's optimal plans", ...
std::string plan_name(const std::string &robot_behaviour);

// "{a, b}" or "{} (the empty design)".
std::string design_set(const std::vector<std::string> &design);

} // namespace envdesign::client
