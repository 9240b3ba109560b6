#pragma once
// The report of `envdesign report`: one self-contained HTML page (no external files, plots
// inline as SVG) that a site manager can read: the recommendation and its cost, the
// objective's breakdown, each task before and after with its plans, the value of each
// chosen modification, break-even, the ranking, and plots drawn with gnuplot.

#include "envdesign/design_result_t.hpp"

#include <stdexcept>
#include <string>

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

// The page for `result` (which must have a design and an explanation); `title` names the
// spec. Throws PlotError when gnuplot cannot draw.
std::string report_html(const envdesign::design_result_t &result, const std::string &title);

// Text with &, <, >, " escaped.
std::string html_escape(const std::string &text);

} // namespace envdesign::client
