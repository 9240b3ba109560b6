#pragma once
// `envdesign report SPEC -o FILE.html [--ranking N]`: runs the design search locally, as
// `envdesign design` does, and writes one self-contained HTML page of the answer
// (clients/cpp/src/report_html.h).

#include <CLI/CLI.hpp>

#include <string>

namespace envdesign::cli {

struct ReportFlags {
    std::string spec;
    std::string output;
    int ranking = 5; // designs in the ranking and the plots
    int workers = 1;
    double time_limit_s = -1; // < 0: the spec's time_limit_s
    std::string heuristic = "lmcut";
};

void add_report_flags(CLI::App &command, ReportFlags &flags);

// Returns 0 (written), 2 bad input, 4 the time limit stopped the search (the page shows the
// best design found), 1 gnuplot failed or the file could not be written.
int run_report(const ReportFlags &flags);

} // namespace envdesign::cli
