#pragma once
// The check of every number flag (design/model/numbers.h's rule): CLI11's own PositiveNumber and
// Range let NaN and inf through, and a service then ran with them.
//
//   app.add_option("--time-limit", seconds)->check(service::number_in(design::TIME_LIMIT_S));

#include "design/model/numbers.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <sstream>
#include <string>

namespace envdesign::service {

inline CLI::Validator number_in(design::NumberRange range) {
    std::ostringstream description;
    description << "NUMBER in [" << range.low << ", " << range.high << "]";
    return CLI::Validator(
        [range](std::string &text) -> std::string {
            char *end = nullptr;
            double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                return "'" + text + "' is not a number";
            auto why = design::number_problem(value, range);
            return why ? *why : std::string();
        },
        description.str());
}

// A duration in seconds that must be positive: at least 1 ms, at most TIME_LIMIT_S's top.
inline constexpr design::NumberRange POSITIVE_SECONDS{1e-3, design::TIME_LIMIT_S.high};

} // namespace envdesign::service
