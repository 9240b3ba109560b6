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

// The terminal and style every plot shares; `height` in pixels.
std::string header(int height) {
    return "set terminal svg size 900," + std::to_string(height) +
           " dynamic font 'sans,12' background '#ffffff'\n"
           "set key outside right top noenhanced\n"
           "set grid\n";
}

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

// One design's objective at each x of a plot.
struct Line {
    std::string title;
    bool chosen = false;
    std::vector<std::pair<double, double>> points; // finite values only
};

// The y range of `lines`: linear from 0 when they span less than a factor 20 (or touch 0),
// else logarithmic, so that the chosen design never lies flat on the axis.
std::string y_axis(const std::vector<Line> &lines) {
    double low = INFINITY, high = -INFINITY;
    for (const auto &l : lines)
        for (const auto &[x, y] : l.points)
            low = std::min(low, y), high = std::max(high, y);
    std::ostringstream gp;
    if (!std::isfinite(low))
        return "set yrange [0:1]\n";
    if (low > 0 && high / low > 20) {
        // Labels at 1, 2, 5 x 10^k: a reader (and a test) can tell the log axis by them.
        gp << "set logscale y\nset yrange [" << low / 1.5 << ":" << high * 1.5 << "]\nset ytics (";
        const char *sep = "";
        for (double decade = std::pow(10, std::floor(std::log10(low / 1.5))); decade <= high * 1.5;
             decade *= 10)
            for (double step : {1, 2, 5})
                if (step * decade >= low / 1.5 && step * decade <= high * 1.5)
                    gp << sep << step * decade, sep = ", ";
        gp << ")\n";
    } else
        gp << "set yrange [" << std::min(0.0, low * 1.1) << ":" << std::max(high * 1.1, 1e-9)
           << "]\n";
    return gp.str();
}

// One panel: `lines` as data blocks $<prefix>N and a plot command, the chosen one wide.
std::string panel(const std::vector<Line> &lines, const std::string &prefix) {
    std::ostringstream gp;
    for (std::size_t d = 0; d < lines.size(); ++d) {
        gp << "$" << prefix << d << " << EOD\n";
        for (const auto &[x, y] : lines[d].points)
            gp << x << " " << y << "\n";
        gp << "EOD\n";
    }
    gp << y_axis(lines) << "plot ";
    for (std::size_t d = 0; d < lines.size(); ++d)
        gp << (d ? ", " : "") << "$" << prefix << d << " with lines lw "
           << (lines[d].chosen ? 3 : 1.5) << " title " << quoted(lines[d].title);
    gp << "\n";
    return gp.str();
}

// The designs' objectives against T or alpha: the chosen design and its rivals on an axis
// of their own (log when they span more than a factor 20), the empty design apart below, on
// its own axis: on one linear axis it dwarfs the rest (issue 25).
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
    std::vector<Line> rivals, empty;
    for (std::size_t d = 0; d < designs.size(); ++d) {
        Line line{label(designs[d]) + (d == 0 ? " (chosen)" : ""), d == 0, {}};
        int steps = by_horizon ? static_cast<int>(right) : 200;
        for (int i = by_horizon ? 1 : 0; i <= steps; ++i) {
            double x = by_horizon ? i : right * i / steps;
            double y = objective_with(w, designs[d], by_horizon ? static_cast<int>(x) : w.horizon,
                                      by_horizon ? w.alpha : x);
            if (std::isfinite(y))
                line.points.push_back({x, y});
        }
        bool apart = designs[d].design.empty() && d != 0;
        (apart ? empty : rivals).push_back(std::move(line));
        if (apart)
            empty.back().title = "{} (the empty design, own axis)";
    }
    std::ostringstream gp;
    gp << header(empty.empty() ? 400 : 560);
    std::string x_label =
        by_horizon ? "horizon T (uses of the environment)" : "alpha (weight of inexplicability)";
    gp << "set arrow from " << spec_x << ", graph 0 to " << spec_x
       << ", graph 1 nohead dt 2 lc rgb '#555555'\n";
    gp << "set label " << quoted(by_horizon ? "spec's T" : "spec's alpha") << " at " << spec_x
       << ", graph 0.95 offset 0.5,0 noenhanced\n";
    double chosen_y = objective_with(w, designs[0], w.horizon, w.alpha);
    if (std::isfinite(chosen_y))
        gp << "set label 1001 " << quoted(shown(chosen_y)) << " at " << spec_x << ", " << chosen_y
           << " point pt 7 ps 1 offset 0.8,0.8 noenhanced\n";
    gp << "set ylabel 'objective (lower is better)'\n";
    if (empty.empty()) {
        gp << "set xlabel " << quoted(x_label) << "\n" << panel(rivals, "d");
        return run_gnuplot(gp.str());
    }
    gp << "set multiplot\nset lmargin 12\nset rmargin 44\n"
       << "set origin 0,0.36\nset size 1,0.64\nunset xlabel\n"
       << panel(rivals, "d") << "unset label 1001\nunset logscale y\nset ytics autofreq\n"
       << "set origin 0,0\nset size 1,0.38\nset ylabel 'empty design'\nset xlabel "
       << quoted(x_label) << "\n"
       << panel(empty, "e") << "unset multiplot\n";
    return run_gnuplot(gp.str());
}

// The 1-based place of `p` in the ranking.
std::size_t rank_of(const envdesign::design_result_t &r, const envdesign::design_point_t &p) {
    for (std::size_t i = 0; i < r.ranking.size(); ++i)
        if (r.ranking[i].design == p.design)
            return i + 1;
    return 0;
}

struct Bar {
    std::string name;
    envdesign::design_terms_t terms;
};

// Stacked bars of `bars` (alpha * inexplicability, beta * design cost, kappa * robot cost),
// the objective written above each, and a marker on the chosen one's top.
std::string bars_panel(const envdesign::explanation_t &w, const std::vector<Bar> &bars,
                       const std::string &block, const std::string &chosen_title, bool key) {
    auto finite = [](double v) { return std::isfinite(v) ? v : 0.0; };
    std::ostringstream gp;
    double top = 0;
    gp << "$" << block << " << EOD\n";
    for (const auto &[name, t] : bars) {
        double sum = finite(w.alpha * t.inexplicability) + finite(w.beta * t.design_cost) +
                     finite(w.kappa * t.robot_cost);
        top = std::max(top, sum);
        gp << data_label(name) << " " << finite(w.alpha * t.inexplicability) << " "
           << finite(w.beta * t.design_cost) << " " << finite(w.kappa * t.robot_cost) << " " << sum
           << " " << data_label(shown(t.objective)) << "\n";
    }
    gp << "EOD\n";
    gp << "set yrange [0:" << std::max(top * 1.18, 1e-9) << "]\n"
       << (key ? "set key\n" : "unset key\n");
    gp << "plot $" << block
       << " using 2:xtic(1) title 'alpha x inexplicability' lc rgb '#d95f02', "
          "'' using 3 title 'beta x design cost' lc rgb '#7570b3', "
          "'' using 4 title 'kappa x robot cost' lc rgb '#1b9e77', "
          "'' using 0:5:6 with labels offset 0,0.8 notitle";
    if (!chosen_title.empty())
        gp << ", '' every ::0::0 using 0:5 with points pt 7 ps 1.2 lc rgb '#000000' title "
           << quoted(chosen_title);
    gp << "\n";
    return gp.str();
}

// The weighted terms of the chosen design and the next ones of the ranking on one axis, the
// empty design's on its own axis beside them (it would flatten the rest).
std::string breakdown_plot(const envdesign::design_result_t &r) {
    const auto &w = r.explanation;
    std::vector<Bar> bars{{"chosen", r.best}};
    for (const auto &p : r.ranking)
        if (p.design != r.design && !std::isnan(p.expected_ie) && bars.size() < 4 &&
            std::isfinite(p.terms.objective))
            bars.push_back({"rank " + std::to_string(rank_of(r, p)), p.terms});
    std::string chosen = label(r.explanation.chosen) + " (chosen)";
    std::ostringstream gp;
    gp << header(400);
    gp << "set style data histograms\nset style histogram rowstacked\n"
          "set style fill solid 0.85 border -1\nset boxwidth 0.6\nset xtics noenhanced\n";
    bool apart = r.has_baseline && !r.design.empty();
    if (!apart) {
        gp << "set ylabel 'weighted objective terms'\n"
           << bars_panel(w, bars, "bars", chosen, true);
        return run_gnuplot(gp.str());
    }
    gp << "set multiplot\nset key outside below\nset origin 0,0\nset size 0.74,1\n"
          "set ylabel 'weighted objective terms'\n"
       << bars_panel(w, bars, "bars", chosen, true)
       << "set origin 0.74,0\nset size 0.26,1\nset ylabel 'empty design (own axis)'\n"
       << bars_panel(w, {{"empty design", r.baseline}}, "empty", "", false) << "unset multiplot\n";
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
