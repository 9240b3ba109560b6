#pragma once
// Progress of the design search on stderr: on a terminal a live bar (configurations done /
// total, best objective, planner runs, cache hits), redrawn at most ten times a second;
// otherwise nothing until the one summary line of finish().

#include "design/search/design_search.h"

#include <chrono>
#include <cstdio>

namespace envdesign::cli {

class ProgressPrinter {
public:
    // `live`: draw the bar (pass isatty(fileno(out))).
    ProgressPrinter(std::FILE *out, bool live) : out_(out), live_(live) {}

    void update(const design::SearchProgress &progress);
    // Clears the bar and prints the summary line.
    void finish(const design::DesignResult &result);

    // The summary line, without a newline (also for logs and tests).
    static std::string summary(const design::DesignResult &result);

private:
    std::FILE *out_;
    bool live_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_draw_{};
};

} // namespace envdesign::cli
