#include "report_html.h"
#include "result_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace envdesign::client {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t MOST_SERIES = 5;

// A scratch directory, removed when it goes out of scope.
class ScratchDir {
public:
    ScratchDir() {
        std::string pattern = (fs::temp_directory_path() / "envdesign-plot-XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            throw PlotError("cannot make a scratch directory for gnuplot");
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path &path() const { return path_; }

private:
    fs::path path_;
};

// Runs gnuplot on `script` (which writes SVG to standard output) and returns the <svg>
// element, without the XML prolog, ready to sit inside HTML.
std::string run_gnuplot(const std::string &script) {
    ScratchDir dir;
    fs::path in = dir.path() / "plot.gp", out = dir.path() / "plot.svg";
    std::ofstream(in) << script;
    std::string command = "gnuplot '" + in.string() + "' > '" + out.string() + "' 2> '" +
                          (dir.path() / "err.txt").string() + "'";
    if (std::system(command.c_str()) != 0) {
        std::ifstream err(dir.path() / "err.txt");
        std::stringstream why;
        why << err.rdbuf();
        throw PlotError("gnuplot failed (is it installed?): " + why.str());
    }
    std::ifstream svg(out);
    std::stringstream text;
    text << svg.rdbuf();
    std::string s = text.str();
    auto start = s.find("<svg");
    if (start == std::string::npos)
        throw PlotError("gnuplot wrote no SVG");
    return s.substr(start);
}

// A gnuplot string literal: single quotes doubled.
std::string quoted(const std::string &text) {
    std::string out = "'";
    for (char c : text)
        out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

// A string field of a gnuplot data block: double quotes, none inside.
std::string data_label(std::string text) {
    text.erase(std::remove(text.begin(), text.end(), '"'), text.end());
    return "\"" + text + "\"";
}

std::string label(const envdesign::design_point_t &p) {
    std::string out = p.design.empty() ? "{}" : "{";
    for (std::size_t i = 0; i < p.design.size(); ++i)
        out += (i ? ", " : "") + p.design[i] + (i + 1 == p.design.size() ? "}" : "");
    return out;
}

const char *HEADER = "set terminal svg size 900,400 dynamic font 'sans,12' background '#ffffff'\n"
                     "set key outside right top noenhanced\n"
                     "set grid\n";

// The designs drawn: the ranking (or the chosen one), then the baseline if not among them.
std::vector<envdesign::design_point_t> series(const envdesign::design_result_t &r) {
    std::vector<envdesign::design_point_t> out;
    for (const auto &p : r.ranking)
        if (!std::isnan(p.expected_ie) && out.size() < MOST_SERIES)
            out.push_back(p);
    if (out.empty())
        out.push_back(r.explanation.chosen);
    for (const auto &m : r.explanation.marginal)
        if (m.evaluated && out.size() < MOST_SERIES + 1)
            out.push_back(m.without);
    bool has_empty =
        std::any_of(out.begin(), out.end(), [](const auto &p) { return p.design.empty(); });
    if (!has_empty && r.has_baseline && !r.explanation.tasks.empty()) {
        envdesign::design_point_t empty{};
        empty.expected_ie = empty.expected_robot_cost = 0;
        double ie = 0, cost = 0;
        bool known = true;
        for (std::size_t i = 0; i < r.explanation.tasks.size(); ++i) {
            const auto &t = r.explanation.tasks[i];
            known = known && t.has_baseline;
            if (t.baseline.probability <= 0)
                continue;
            ie += t.baseline.probability * t.baseline.ie;
            cost += t.baseline.probability * t.baseline.robot_cost;
        }
        empty.expected_ie = ie;
        empty.expected_robot_cost = cost;
        if (known)
            out.push_back(empty);
    }
    std::vector<envdesign::design_point_t> unique;
    for (const auto &p : out)
        if (std::none_of(unique.begin(), unique.end(),
                         [&](const auto &u) { return u.design == p.design; }))
            unique.push_back(p);
    return unique;
}

// One line per design: its objective at each x (T or alpha), from its design point.
std::string lines_plot(const envdesign::design_result_t &r, bool by_horizon) {
    const auto &w = r.explanation;
    auto designs = series(r);
    double spec_x = by_horizon ? w.horizon : w.alpha;
    double right = by_horizon ? std::max(20.0, 2.0 * w.horizon) : std::max(2.0, 3.0 * w.alpha);
    const auto &b = w.break_even;
    if (by_horizon && b.horizon_up.found)
        right = std::max(right, 1.3 * b.horizon_up.at);
    if (!by_horizon && b.alpha_up.found)
        right = std::max(right, 1.5 * b.alpha_up.at);
    std::ostringstream gp;
    gp << HEADER;
    gp << "set xlabel "
       << quoted(by_horizon ? "horizon T (uses of the environment)"
                            : "alpha (weight of inexplicability)")
       << "\n";
    gp << "set ylabel 'objective (lower is better)'\n";
    gp << "set arrow from " << spec_x << ", graph 0 to " << spec_x
       << ", graph 1 nohead dt 2 lc rgb '#555555'\n";
    gp << "set label " << quoted(by_horizon ? "spec's T" : "spec's alpha") << " at " << spec_x
       << ", graph 0.95 offset 0.5,0 noenhanced\n";
    for (std::size_t d = 0; d < designs.size(); ++d) {
        gp << "$d" << d << " << EOD\n";
        int steps = by_horizon ? static_cast<int>(right) : 200;
        for (int i = by_horizon ? 1 : 0; i <= steps; ++i) {
            double x = by_horizon ? i : right * i / steps;
            double y = objective_with(w, designs[d], by_horizon ? static_cast<int>(x) : w.horizon,
                                      by_horizon ? w.alpha : x);
            if (std::isfinite(y))
                gp << x << " " << y << "\n";
        }
        gp << "EOD\n";
    }
    gp << "plot ";
    for (std::size_t d = 0; d < designs.size(); ++d)
        gp << (d ? ", " : "") << "$d" << d << " with lines lw " << (d == 0 ? 3 : 1.5) << " title "
           << quoted(label(designs[d]) + (d == 0 ? " (chosen)" : ""));
    gp << "\n";
    return run_gnuplot(gp.str());
}

// The 1-based place of `p` in the ranking.
std::size_t rank_of(const envdesign::design_result_t &r, const envdesign::design_point_t &p) {
    for (std::size_t i = 0; i < r.ranking.size(); ++i)
        if (r.ranking[i].design == p.design)
            return i + 1;
    return 0;
}

// Stacked bars: alpha * inexplicability, beta * design cost, kappa * robot cost.
std::string breakdown_plot(const envdesign::design_result_t &r) {
    const auto &w = r.explanation;
    std::vector<std::pair<std::string, envdesign::design_terms_t>> bars{{"chosen", r.best}};
    if (r.has_baseline)
        bars.push_back({"empty design", r.baseline});
    for (const auto &p : r.ranking)
        if (p.design != r.design && !std::isnan(p.expected_ie) && bars.size() < 4 &&
            std::isfinite(p.terms.objective))
            bars.push_back({"rank " + std::to_string(rank_of(r, p)), p.terms});
    std::ostringstream gp;
    gp << HEADER;
    gp << "set style data histograms\nset style histogram rowstacked\n"
          "set style fill solid 0.85 border -1\nset boxwidth 0.6\n"
          "set ylabel 'weighted objective terms'\nset xtics noenhanced\n";
    gp << "$bars << EOD\n";
    for (const auto &[name, t] : bars) {
        auto finite = [](double v) { return std::isfinite(v) ? v : 0.0; };
        gp << data_label(name) << " " << finite(w.alpha * t.inexplicability) << " "
           << finite(w.beta * t.design_cost) << " " << finite(w.kappa * t.robot_cost) << "\n";
    }
    gp << "EOD\n";
    gp << "plot $bars using 2:xtic(1) title 'alpha x inexplicability' lc rgb '#d95f02', "
          "'' using 3 title 'beta x design cost' lc rgb '#7570b3', "
          "'' using 4 title 'kappa x robot cost' lc rgb '#1b9e77'\n";
    return run_gnuplot(gp.str());
}

} // namespace

ReportPlots report_plots(const envdesign::design_result_t &result) {
    // EXPLAINING: the objective at other T or alpha needs each task's choice again, which
    // the design points do not carry (their expectations are NaN): no lines to draw.
    bool explaining = std::any_of(result.tasks.begin(), result.tasks.end(),
                                  [](const auto &t) { return t.has_explanation; });
    if (explaining)
        return {"", "", breakdown_plot(result)};
    return {lines_plot(result, true), lines_plot(result, false), breakdown_plot(result)};
}

} // namespace envdesign::client
