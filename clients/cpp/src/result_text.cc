#include "plan_diff.h"
#include "result_format.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace envdesign::client {
namespace {

using Terms = envdesign::design_terms_t;
using Weights = envdesign::explanation_t;

void terms_line(std::ostream &out, const char *label, const Terms &t) {
    out << label << shown(t.objective) << " (inexplicability " << shown(t.inexplicability)
        << ", design cost " << shown(t.design_cost) << ", robot cost " << shown(t.robot_cost);
    if (t.explanation != 0) // EXPLAINING: the explanations told over the horizon
        out << ", explanation " << shown(t.explanation);
    out << ")\n";
}

// "52.23 = 1 x 12.83 inexplicability + 30 x 1.5 design cost + 0.25 x 244 robot cost"
void weighted_line(std::ostream &out, const char *label, const Terms &t, const Weights &w) {
    out << label << shown(t.objective) << " = " << shown(w.alpha * t.inexplicability)
        << " inexplicability (" << shown(w.alpha) << " x " << shown(t.inexplicability) << ") + "
        << shown(w.beta * t.design_cost) << " design cost (" << shown(w.beta) << " x "
        << shown(t.design_cost) << ") + " << shown(w.kappa * t.robot_cost) << " robot cost ("
        << shown(w.kappa) << " x " << shown(t.robot_cost) << ")";
    if (t.explanation != 0) // EXPLAINING: its weight is 1 (design/behaviour/explaining.h)
        out << " + " << shown(t.explanation) << " explanation";
    out << "\n";
}

// EXPLAINING: "  explains: +init (a), -pre move (b)" or "  acts explicably (explanation: ...)".
void explanation_line(std::ostream &out, const envdesign::task_result_t &t) {
    if (!t.has_explanation)
        return;
    out << (t.explained ? "  explains" : "  acts explicably (explanation");
    if (!t.explanation.found) {
        out << ": none)\n";
        return;
    }
    out << ":";
    for (std::size_t i = 0; i < t.explanation.differences.size(); ++i)
        out << (i ? ", " : " ") << t.explanation.differences[i];
    if (t.explanation.differences.empty())
        out << " nothing to tell";
    out << (t.explained ? "\n" : ")\n");
}

void least_line(std::ostream &out, const envdesign::design_result_t &r) {
    const Weights &w = r.explanation;
    double least = w.least_inexplicability;
    out << "  least inexplicability term possible: " << shown(least) << " (every IE "
        << shown(w.least_ie) << " over the horizon: f_T(" << shown(w.least_ie)
        << ") with T = " << w.horizon << ", gamma = " << shown(w.gamma) << ")";
    if (std::abs(r.best.inexplicability - least) <= 1e-9 * std::max(1.0, least))
        out << ": the chosen design is as explicable as it gets";
    out << "\n";
}

void plan_line(std::ostream &out, const char *label, const std::vector<std::string> &plan) {
    out << "    " << std::left << std::setw(22) << label;
    if (plan.empty())
        out << " (empty plan)";
    for (const auto &step : plan)
        out << " " << step;
    out << "\n";
}

void diff_line(std::ostream &out, const char *label, const std::vector<std::string> &pi,
               const std::vector<std::string> &other) {
    auto diff = plan_diff(pi, other);
    out << "    " << std::left << std::setw(22) << label;
    if (!plans_differ(diff)) {
        out << " the same plan\n";
        return;
    }
    for (const auto &step : diff)
        if (step.side != DiffSide::BOTH)
            out << " " << (step.side == DiffSide::ONLY_FIRST ? "+" : "-") << step.action;
    out << "\n";
}

void row(std::ostream &out, const char *label, double before, double after, bool known) {
    out << "    " << std::left << std::setw(28) << label << std::right << std::setw(12)
        << (known ? shown(before) : "?") << std::setw(12) << shown(after) << "\n";
}

void task_block(std::ostream &out, const std::string &behaviour, const envdesign::task_result_t &t,
                const envdesign::task_explanation_t &e) {
    const auto &b = e.baseline;
    out << "task " << t.name << " (probability " << shown(t.probability) << "):\n";
    explanation_line(out, t);
    out << "    " << std::left << std::setw(28) << "" << std::right << std::setw(12)
        << "empty design" << std::setw(12) << "chosen"
        << "\n";
    row(out, "IE", b.ie, t.ie, e.has_baseline);
    row(out, "robot cost c_R(pi)", b.robot_cost, t.robot_cost, e.has_baseline);
    row(out, "human optimal cost c_H*", b.has_human_optimal_cost ? b.human_optimal_cost : NAN,
        t.has_human_optimal_cost ? t.human_optimal_cost : NAN, e.has_baseline);
    row(out, "human cost of pi c_H(pi)", b.human_plan_cost, t.human_plan_cost, e.has_baseline);
    out << "  plans under the chosen design:\n";
    if (e.has_robot_plan)
        plan_line(out, "robot's optimal:", e.robot_plan);
    plan_line(out, "pi:", t.plan);
    out << "      (pi is " << plan_name(behaviour) << ")\n";
    if (e.has_expected_plan)
        plan_line(out, "observers expect:", e.expected_plan);
    if (e.has_robot_plan)
        diff_line(out, "pi vs robot's:", t.plan, e.robot_plan);
    if (e.has_expected_plan)
        diff_line(out, "pi vs expected:", t.plan, e.expected_plan);
    if (e.has_expected_plan && t.has_human_optimal_cost &&
        t.human_plan_cost == t.human_optimal_cost)
        out << "    (pi costs observers what their expected plan costs: they find it just as "
               "good)\n";
}

void marginal_block(std::ostream &out, const envdesign::design_result_t &r) {
    if (r.explanation.marginal.empty())
        return;
    out << "value of each chosen modification (the objective without it):\n";
    for (const auto &m : r.explanation.marginal) {
        out << "  " << m.modification << ": ";
        if (!m.evaluated) {
            out << "not evaluated (time limit)\n";
            continue;
        }
        double value = m.without.terms.objective - r.best.objective;
        out << shown(m.without.terms.objective) << " without it (" << (value >= 0 ? "+" : "")
            << shown(value) << ")\n";
    }
}

void crossing_line(std::ostream &out, const char *what, const envdesign::crossing_t &c) {
    out << "    " << what << " " << shown(c.at) << ": " << design_set(c.rival.design) << "\n";
}

void break_even_block(std::ostream &out, const envdesign::design_result_t &r) {
    const auto &b = r.explanation.break_even;
    const Weights &w = r.explanation;
    if (b.designs_compared == 0) {
        out << "break-even: not computed (with robot_behaviour EXPLAINING each task's choice "
               "between explaining and acting explicably moves with T and alpha)\n";
        return;
    }
    out << "break-even (among the " << b.designs_compared << " designs evaluated in full):\n";
    out << "  horizon: the chosen design ranks first for T in ["
        << (b.horizon_down.found ? static_cast<long long>(b.horizon_down.at) + 1 : 1LL) << ", "
        << (b.horizon_up.found ? std::to_string(static_cast<long long>(b.horizon_up.at) - 1)
                               : std::to_string(b.horizon_limit) + "+")
        << "] (spec: T = " << w.horizon << ")\n";
    if (b.horizon_down.found)
        crossing_line(out, "first before it at T =", b.horizon_down);
    if (b.horizon_up.found)
        crossing_line(out, "first before it at T =", b.horizon_up);
    out << "  alpha: the chosen design ranks first for alpha in ["
        << (b.alpha_down.found ? shown(b.alpha_down.at) : "0") << ", "
        << (b.alpha_up.found ? shown(b.alpha_up.at) : "inf")
        << "] (spec: alpha = " << shown(w.alpha) << ")\n";
    if (b.alpha_down.found)
        crossing_line(out, "below alpha =", b.alpha_down);
    if (b.alpha_up.found)
        crossing_line(out, "above alpha =", b.alpha_up);
}

void explanation_block(std::ostream &out, const envdesign::design_result_t &r) {
    for (std::size_t i = 0; i < r.tasks.size() && i < r.explanation.tasks.size(); ++i)
        task_block(out, r.explanation.robot_behaviour, r.tasks[i], r.explanation.tasks[i]);
    marginal_block(out, r);
    break_even_block(out, r);
}

void ranking_block(std::ostream &out, const envdesign::design_result_t &r) {
    if (r.ranking_size == 0)
        return;
    out << "ranking:\n";
    for (std::size_t i = 0; i < r.ranking.size(); ++i)
        out << "  " << i + 1 << ". " << shown(r.ranking[i].terms.objective) << "  "
            << design_set(r.ranking[i].design) << "\n";
}

} // namespace

std::string result_text(const envdesign::design_result_t &r) {
    std::ostringstream out;
    out << "status: " << r.status;
    if (r.status == "unsolvable" && !r.error.empty())
        out << " (" << r.error << ")";
    out << "\n";
    if (!r.has_design) {
        out << "no configuration was evaluated in time\n";
        return out.str();
    }
    out << "design: " << design_set(r.design) << "\n";
    if (r.has_explanation) {
        weighted_line(out, "objective: ", r.best, r.explanation);
        least_line(out, r);
        if (r.has_baseline)
            weighted_line(out, "baseline (empty design): ", r.baseline, r.explanation);
    } else {
        terms_line(out, "objective: ", r.best);
        if (r.has_baseline)
            terms_line(out, "baseline: ", r.baseline);
    }
    if (r.has_explanation)
        explanation_block(out, r);
    else
        for (const auto &t : r.tasks) {
            out << "task " << t.name << ": ie " << shown(t.ie) << ", robot cost "
                << shown(t.robot_cost) << ", plan";
            for (const auto &step : t.plan)
                out << " " << step;
            out << "\n";
            explanation_line(out, t);
        }
    ranking_block(out, r);
    if (r.has_gap)
        out << "proven gap: " << shown(r.gap) << "\n";
    for (const auto &note : r.notes)
        out << "note: " << note << "\n";
    return out.str();
}

} // namespace envdesign::client
