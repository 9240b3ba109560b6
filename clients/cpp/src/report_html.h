#pragma once
// The report of `envdesign report`: one self-contained HTML page (no external files, plots
// inline as SVG) that a site manager can read: the recommendation and its cost, the
// objective's breakdown, each task before and after with its plans, the value of each
// chosen modification, break-even, the ranking, and plots drawn with gnuplot.

#include "envdesign/design_result_t.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::client {

// gnuplot is missing or failed.
class PlotError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The plots as inline SVG elements (report_plots.cc). `result` must have an explanation.
struct ReportPlots {
    std::string objective_by_horizon; // the top designs' objectives against T
    std::string objective_by_alpha;   // ... against alpha
    std::string cost_breakdown;       // weighted terms of the chosen design, the baseline, ...
};
ReportPlots report_plots(const envdesign::design_result_t &result);

using Plan = std::vector<std::string>;

// What the local `envdesign report` adds to the message, which carries only pi under the
// empty design.
struct ReportExtras {
    // Per task of result.tasks, under the empty design: the plan people expect (an optimal
    // plan of P_H) and the robot's optimal plan (P_R); unset or missing: not solved.
    std::vector<std::optional<Plan>> expected_before;
    std::vector<std::optional<Plan>> robot_optimal_before;
    // HTML the caller drew (a floor spec's pictures, common/floor/floor_draw.h), after the
    // recommendation; empty: none.
    std::string floor_section;
};

// The page for `result` (which must have a design and an explanation); `title` names the
// spec. Throws PlotError when gnuplot cannot draw.
std::string report_html(const envdesign::design_result_t &result, const std::string &title,
                        const ReportExtras &extras = {});

// Text with &, <, >, " escaped.
std::string html_escape(const std::string &text);

} // namespace envdesign::client
