#include "progress.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace envdesign::cli {
namespace {

std::string progress_number(double value) {
    if (std::isinf(value))
        return "inf";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

} // namespace

void ProgressPrinter::update(const design::SearchProgress &p) {
    auto now = std::chrono::steady_clock::now();
    bool last = p.done >= p.total;
    if (!live_ || (!last && now - last_draw_ < std::chrono::milliseconds(100)))
        return;
    last_draw_ = now;
    constexpr int WIDTH = 24;
    int filled = p.total > 0 ? static_cast<int>(WIDTH * static_cast<double>(p.done) / p.total) : 0;
    std::string bar(std::min(filled, WIDTH), '#');
    bar.resize(WIDTH, '-');
    double seconds = std::chrono::duration<double>(now - start_).count();
    if (p.open >= 0) // the witness search: no fixed total, a bound instead
        std::fprintf(out_,
                     "\r%lld visited, %lld open | best %s | least open bound %s | "
                     "%lld planner runs | %.1fs\033[K",
                     p.done, p.open, progress_number(p.best_objective).c_str(),
                     progress_number(p.least_open_bound).c_str(), p.planner_runs, seconds);
    else
        std::fprintf(out_,
                     "\r[%s] %lld/%lld configurations | best %s | %lld planner runs | "
                     "%lld cache hits | %.1fs\033[K",
                     bar.c_str(), p.done, p.total, progress_number(p.best_objective).c_str(),
                     p.planner_runs, p.cache_hits, seconds);
    std::fflush(out_);
    drawn_ = true;
}

std::string ProgressPrinter::summary(const design::DesignResult &r) {
    const design::DesignCounters &c = r.counters;
    // What the search itself did: the exhaustive search considers every subset up to the
    // size limit, the witness search only those it generates; the explanation's evaluations
    // (the result's break-even counts them) come after.
    std::string line = "design: the search considered " + std::to_string(c.configurations_total) +
                       " configurations: " + std::to_string(c.configurations_evaluated) +
                       " evaluated in full, " + std::to_string(c.configurations_abandoned) +
                       " abandoned and " + std::to_string(c.configurations_skipped) +
                       " skipped by the bound";
    if (c.tasks_inherited > 0)
        line += ", " + std::to_string(c.tasks_inherited) + " task evaluations inherited";
    if (c.configurations_pruned > 0)
        line += ", " + std::to_string(c.configurations_pruned) + " pruned as irrelevant";
    line += "; " + std::to_string(c.evaluator.planner_runs) + " planner runs, " +
            std::to_string(c.evaluator.cache_hits) + " cache hits; best " +
            progress_number(r.best ? r.best->objective.value : design::INF) + " (" +
            (r.optimal ? "optimal" : "best found") + ") in " + progress_number(c.seconds) + " s";
    if (r.gap)
        line += "; proven gap " + progress_number(*r.gap);
    return line;
}

void ProgressPrinter::finish(const design::DesignResult &result) {
    if (drawn_)
        std::fprintf(out_, "\r\033[K");
    std::fprintf(out_, "%s\n", summary(result).c_str());
    std::fflush(out_);
}

} // namespace envdesign::cli
