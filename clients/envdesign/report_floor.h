#pragma once
// The floor in `envdesign report`'s page, for a spec `envdesign floor import` wrote (its
// floor.json beside it): the floor with the chosen modifications, and for the most probable
// tasks the robot's path and the path people expect, before and after the design. Drawn by
// common/floor/floor_draw.h, the one picture of a floor (`envdesign floor draw` too).

#include "report_html.h"

#include "envdesign/design_result_t.hpp"

#include <string>

namespace envdesign::cli {

// Tasks drawn on the floor, most probable first (ties: the larger IE before the design).
inline constexpr std::size_t FLOOR_TASKS_DRAWN = 3;

// The HTML section, or "" when no floor.json is beside `spec_path`. A floor.json that does
// not read, or does not fit the result, gives a paragraph saying why (and a warning) instead.
// `extras.expected_before` holds the plans people expected before, per task.
std::string report_floor_section(const std::string &spec_path,
                                 const envdesign::design_result_t &result,
                                 const client::ReportExtras &extras);

} // namespace envdesign::cli
