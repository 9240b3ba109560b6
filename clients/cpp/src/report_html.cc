#include "report_html.h"

#include "plan_diff.h"
#include "result_format.h"

#include <cmath>
#include <sstream>

namespace envdesign::client {
namespace {

using std::ostream;

const char *STYLE = R"(<style>
body{font-family:system-ui,sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222;background:#fff}
h1{font-size:1.6em;margin-bottom:.2em}h2{font-size:1.25em;border-bottom:2px solid #ddd;padding-bottom:.2em;margin-top:1.6em}
.box{background:#eef6ee;border:1px solid #9c9;border-radius:6px;padding:.8em 1.2em;font-size:1.1em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.3em .7em;text-align:right}
th{background:#f3f3f3}td.l,th.l{text-align:left}.plan{font-family:monospace;font-size:.9em}
.differs{background:#ffd966}.muted{color:#666;font-size:.9em}
figure{margin:1em 0}figcaption{color:#444;font-size:.95em}
.floorpair{display:flex;gap:1em}.floorpair figure{margin:.5em 0;flex:1}figure svg{max-width:100%;height:auto}
</style>)";

std::string h(const std::string &text) { return html_escape(text); }

std::string set_of(const std::vector<std::string> &design) { return h(design_set(design)); }

void recommendation(ostream &out, const envdesign::design_result_t &r) {
    const auto &w = r.explanation;
    out << "<div class=box><p><b>Recommendation:</b> " << set_of(r.design) << "</p><p>";
    out << "Design cost " << shown(r.best.design_cost)
        << " (weighted: " << shown(w.beta * r.best.design_cost) << "). Objective "
        << shown(r.best.objective);
    if (r.has_baseline) {
        double saved = r.baseline.objective - r.best.objective;
        out << " against " << shown(r.baseline.objective) << " without any modification";
        if (std::isfinite(saved))
            out << ": " << shown(saved) << " better";
    }
    out << " (lower is better; status: " << h(r.status) << ").</p></div>\n";
}

void term_row(ostream &out, const char *name, double weight, double chosen, double baseline,
              bool has_baseline) {
    out << "<tr><td class=l>" << name << "</td><td>" << shown(weight) << "</td><td>"
        << shown(chosen) << "</td><td>" << shown(weight * chosen) << "</td>";
    if (has_baseline)
        out << "<td>" << shown(baseline) << "</td><td>" << shown(weight * baseline) << "</td>";
    out << "</tr>\n";
}

void breakdown(ostream &out, const envdesign::design_result_t &r) {
    const auto &w = r.explanation;
    const auto &b = r.baseline;
    out << "<h2>Where the objective comes from</h2>\n<table><tr><th class=l>term</th>"
           "<th>weight</th><th>chosen</th><th>weighted</th>";
    if (r.has_baseline)
        out << "<th>empty design</th><th>weighted</th>";
    out << "</tr>\n";
    term_row(out, "inexplicability f_T(E[IE])", w.alpha, r.best.inexplicability, b.inexplicability,
             r.has_baseline);
    term_row(out, "design cost C", w.beta, r.best.design_cost, b.design_cost, r.has_baseline);
    term_row(out, "robot cost T &middot; E[c_R]", w.kappa, r.best.robot_cost, b.robot_cost,
             r.has_baseline);
    out << "<tr><th class=l>objective</th><td></td><td></td><th>" << shown(r.best.objective)
        << "</th>";
    if (r.has_baseline)
        out << "<td></td><th>" << shown(b.objective) << "</th>";
    out << "</tr></table>\n<p class=muted>The least inexplicability term possible is "
        << shown(w.least_inexplicability) << ": every task with IE " << shown(w.least_ie)
        << " (its plan is exactly what observers expect), over T = " << w.horizon
        << " uses discounted by gamma = " << shown(w.gamma) << ".</p>\n";
}

// `plan`'s steps, those not in `against` marked; `against` unset: none marked.
void plan_cell(ostream &out, const std::optional<Plan> &plan, const std::optional<Plan> &against) {
    out << "<td class='l plan'>";
    if (!plan) {
        out << "not solved</td>";
        return;
    }
    if (plan->empty())
        out << "(empty plan)";
    for (const auto &step : plan_diff(against.value_or(*plan), *plan)) {
        if (step.side == DiffSide::ONLY_FIRST)
            continue; // a step of the other plan
        out << (step.side == DiffSide::ONLY_SECOND ? "<span class=differs>" : "<span>")
            << h(step.action) << "</span><br>";
    }
    out << "</td>";
}

std::optional<Plan> at(const std::vector<std::optional<Plan>> &plans, std::size_t i) {
    return i < plans.size() ? plans[i] : std::nullopt;
}

// The plans before and after: what people expected before beside what the robot did before
// and does after, then what people expect after. The robot's steps people did not expect
// before are marked, and in an expected plan the steps the robot does not take then.
void plans_table(ostream &out, const std::string &behaviour, const envdesign::task_result_t &t,
                 const envdesign::task_explanation_t &e, const std::optional<Plan> &expected_before,
                 const std::optional<Plan> &robot_optimal_before) {
    std::optional<Plan> robot_before, expected_after, robot_optimal_after;
    if (e.has_baseline)
        robot_before = e.baseline.plan;
    if (e.has_expected_plan)
        expected_after = e.expected_plan;
    if (e.has_robot_plan)
        robot_optimal_after = e.robot_plan;
    out << "<table class=plans><tr><th class=l>people expected, before</th><th class=l>the "
           "robot, before</th><th class=l>the robot, after</th><th class=l>people expect, "
           "after</th></tr><tr>";
    plan_cell(out, expected_before, robot_before);
    plan_cell(out, robot_before, expected_before);
    plan_cell(out, t.plan, expected_before);
    plan_cell(out, expected_after, t.plan);
    out << "</tr></table><p class=muted>The robot's plan is " << h(plan_name(behaviour))
        << " (&pi;); what people expect is an optimal plan of their model. Marked: the robot's "
           "steps people did not expect before the design; in a plan people expect, the steps "
           "the robot does not take then.";
    if (t.has_human_optimal_cost && t.human_plan_cost == t.human_optimal_cost)
        out << " After the design, &pi; costs people what their expected plan costs: they find "
               "it just as good.";
    out << "</p>\n";
    bool before_differs =
        robot_optimal_before && robot_before && *robot_optimal_before != *robot_before;
    bool after_differs = robot_optimal_after && *robot_optimal_after != t.plan;
    if (!before_differs && !after_differs)
        return;
    out << "<table><tr><th class=l>the robot's optimal plan, before</th><th class=l>the robot's "
           "optimal plan, after</th></tr><tr>";
    plan_cell(out, robot_optimal_before, robot_before);
    plan_cell(out, robot_optimal_after, t.plan);
    out << "</tr></table><p class=muted>Marked: steps not in &pi; at that time.</p>\n";
}

void task_section(ostream &out, const std::string &behaviour, const envdesign::task_result_t &t,
                  const envdesign::task_explanation_t &e,
                  const std::optional<Plan> &expected_before,
                  const std::optional<Plan> &robot_optimal_before) {
    const auto &b = e.baseline;
    auto cell = [&](double v, bool known) { return "<td>" + (known ? shown(v) : "?") + "</td>"; };
    out << "<h3>Task " << h(t.name) << " (probability " << shown(t.probability) << ")</h3>\n";
    if (t.has_explanation) { // robot_behaviour EXPLAINING: the option taken and what is told
        out << "<p>The robot "
            << (t.explained ? "follows its own plan and explains" : "acts explicably")
            << "; the explanation " << (t.explained ? "it tells" : "it would need") << ": ";
        if (!t.explanation.found)
            out << "none exists";
        else if (t.explanation.differences.empty())
            out << "nothing to tell";
        for (std::size_t i = 0; i < t.explanation.differences.size(); ++i)
            out << (i ? ", " : "") << "<code>" << h(t.explanation.differences[i]) << "</code>";
        out << ".</p>\n";
    }
    out << "<table><tr><th class=l></th><th>empty design</th><th>chosen design</th></tr>\n";
    out << "<tr><td class=l>inexplicability IE</td>" << cell(b.ie, e.has_baseline)
        << cell(t.ie, true) << "</tr>\n";
    out << "<tr><td class=l>robot cost c_R(&pi;)</td>" << cell(b.robot_cost, e.has_baseline)
        << cell(t.robot_cost, true) << "</tr>\n";
    out << "<tr><td class=l>human optimal cost c_H*</td>"
        << cell(b.human_optimal_cost, e.has_baseline && b.has_human_optimal_cost)
        << cell(t.human_optimal_cost, t.has_human_optimal_cost) << "</tr>\n";
    out << "<tr><td class=l>human cost of &pi;, c_H(&pi;)</td>"
        << cell(b.human_plan_cost, e.has_baseline) << cell(t.human_plan_cost, true)
        << "</tr></table>\n";
    plans_table(out, behaviour, t, e, expected_before, robot_optimal_before);
}

void marginal_section(ostream &out, const envdesign::design_result_t &r) {
    if (r.explanation.marginal.empty())
        return;
    out << "<h2>What each modification is worth</h2>\n<table><tr><th class=l>modification</th>"
           "<th>objective without it</th><th>increase</th></tr>\n";
    for (const auto &m : r.explanation.marginal) {
        out << "<tr><td class=l>" << h(m.modification) << "</td>";
        if (m.evaluated)
            out << "<td>" << shown(m.without.terms.objective) << "</td><td>"
                << shown(m.without.terms.objective - r.best.objective) << "</td>";
        else
            out << "<td>not evaluated</td><td></td>";
        out << "</tr>\n";
    }
    out << "</table>\n";
}

void crossing(ostream &out, const char *what, const envdesign::crossing_t &c) {
    if (c.found)
        out << "<li>" << what << " " << shown(c.at) << ": " << set_of(c.rival.design)
            << " ranks first there</li>\n";
}

void break_even_section(ostream &out, const envdesign::design_result_t &r) {
    const auto &b = r.explanation.break_even;
    out << "<h2>When would the answer change?</h2>\n";
    if (b.designs_compared == 0) {
        out << "<p>Not computed: with robot_behaviour EXPLAINING each task's choice between "
               "explaining and acting explicably moves with T and alpha.</p>\n";
        return;
    }
    out << "<p>Among the " << b.designs_compared
        << " designs whose every task was evaluated, by the search or for this page (a design "
           "never evaluated may change the answer sooner):</p><ul>\n";
    crossing(out, "with fewer uses, at T =", b.horizon_down);
    crossing(out, "with more uses, at T =", b.horizon_up);
    if (!b.horizon_up.found)
        out << "<li>no other design ranks first for T up to " << b.horizon_limit << "</li>\n";
    crossing(out, "caring less about explicability, at alpha =", b.alpha_down);
    crossing(out, "caring more about explicability, at alpha =", b.alpha_up);
    out << "</ul>\n";
}

void ranking_section(ostream &out, const envdesign::design_result_t &r) {
    if (r.ranking.empty())
        return;
    out << "<h2>The best designs</h2>\n<table><tr><th>#</th><th class=l>design</th>"
           "<th>objective</th><th>design cost</th><th>E[IE]</th><th>E[c_R]</th></tr>\n";
    for (std::size_t i = 0; i < r.ranking.size(); ++i) {
        const auto &p = r.ranking[i];
        out << "<tr><td>" << i + 1 << "</td><td class=l>" << set_of(p.design) << "</td><td>"
            << shown(p.terms.objective) << "</td><td>" << shown(p.design_cost) << "</td><td>"
            << shown(p.expected_ie) << "</td><td>" << shown(p.expected_robot_cost)
            << "</td></tr>\n";
    }
    out << "</table>\n";
}

void figure(ostream &out, const std::string &svg, const char *caption) {
    out << "<figure>" << svg << "<figcaption>" << caption << "</figcaption></figure>\n";
}

} // namespace

std::string html_escape(const std::string &text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string report_html(const envdesign::design_result_t &r, const std::string &title,
                        const ReportExtras &extras) {
    ReportPlots plots = report_plots(r);
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>envdesign: " << h(title)
        << "</title>" << STYLE << "</head><body>\n";
    out << "<h1>Environment design for " << h(title) << "</h1>\n";
    recommendation(out, r);
    out << extras.floor_section;
    breakdown(out, r);
    figure(out, plots.cost_breakdown,
           "The weighted terms that add up to each objective: the chosen design, the empty design "
           "and the next designs of the ranking below.");
    out << "<h2>Each task, before and after</h2>\n";
    for (std::size_t i = 0; i < r.tasks.size() && i < r.explanation.tasks.size(); ++i)
        task_section(out, r.explanation.robot_behaviour, r.tasks[i], r.explanation.tasks[i],
                     at(extras.expected_before, i), at(extras.robot_optimal_before, i));
    marginal_section(out, r);
    break_even_section(out, r);
    ranking_section(out, r);
    if (!plots.objective_by_horizon.empty()) {
        out << "<h2>How the objective depends on T and alpha</h2>\n";
        figure(out, plots.objective_by_horizon,
               "Objective of the top designs against the horizon T (other weights as in the "
               "spec).");
        figure(out, plots.objective_by_alpha,
               "Objective of the top designs against alpha (other weights as in the spec).");
    }
    const auto &c = r.counters;
    out << "<p class=muted>The search evaluated " << c.configurations_evaluated << " designs, "
        << c.planner_runs << " planner runs, " << shown(c.seconds)
        << " s. Made by envdesign report; docs/result.md explains every number.</p>\n";
    out << "</body></html>\n";
    return out.str();
}

} // namespace envdesign::client
