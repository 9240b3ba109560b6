#pragma once
// design_result_t -> what `envdesign design` prints: SPEC.md's JSON (the keys and number
// format of the design engine's result_json.h) and the plain text summary.

#include "envdesign/design_result_t.hpp"

#include <string>

namespace envdesign::client {

std::string result_json(const envdesign::design_result_t &result);
std::string result_text(const envdesign::design_result_t &result);

} // namespace envdesign::client
