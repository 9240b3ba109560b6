#include "plan_diff.h"
#include "result_format.h"

namespace envdesign::client {
namespace {

using nlohmann::json;

// robot_behaviour EXPLAINING: the tasks carry their explaining option, and the objective has
// a fourth term, the explanations told over the horizon (weight 1; design/behaviour/explaining.h).
bool explaining(const envdesign::design_result_t &r) {
    for (const auto &t : r.tasks)
        if (t.has_explanation)
            return true;
    return false;
}

json terms_json(const envdesign::design_terms_t &t, bool explaining) {
    json out = {{"inexplicability", json_number(t.inexplicability)},
                {"design_cost", json_number(t.design_cost)},
                {"robot_cost", json_number(t.robot_cost)}};
    if (explaining)
        out["explanation"] = json_number(t.explanation);
    return out;
}

// The terms times their weights: they add up to the objective.
json weighted_json(const envdesign::design_terms_t &t, const envdesign::explanation_t &w,
                   bool explaining) {
    json out = {{"inexplicability", json_number(w.alpha * t.inexplicability)},
                {"design_cost", json_number(w.beta * t.design_cost)},
                {"robot_cost", json_number(w.kappa * t.robot_cost)}};
    if (explaining)
        out["explanation"] = json_number(t.explanation);
    return out;
}

json objective_json(const envdesign::design_terms_t &t, bool explaining) {
    return {{"objective", json_number(t.objective)}, {"terms", terms_json(t, explaining)}};
}

json task_json(const envdesign::task_result_t &t) {
    json out = {{"name", t.name},
                {"probability", t.probability},
                {"ie", json_number(t.ie)},
                {"robot_cost", json_number(t.robot_cost)},
                {"human_plan_cost", json_number(t.human_plan_cost)},
                {"human_optimal_cost",
                 t.has_human_optimal_cost ? json_number(t.human_optimal_cost) : json()},
                {"plan", t.plan}};
    if (t.has_explanation) { // EXPLAINING: the option taken and both options' key values
        out["option"] = t.explained ? "explain" : "act_explicably";
        out["explanation"] = t.explanation.found ? json(t.explanation.differences) : json();
        out["explicable_ie"] = json_number(t.explicable_ie);
        out["robot_optimal_cost"] = json_number(t.explanation.robot_optimal_cost);
    }
    return out;
}

json point_json(const envdesign::design_point_t &p) {
    return {{"design", p.design},
            {"objective", json_number(p.terms.objective)},
            {"design_cost", json_number(p.design_cost)},
            {"terms", terms_json(p.terms, p.terms.explanation != 0)},
            {"expected_ie", json_number(p.expected_ie)},
            {"expected_robot_cost", json_number(p.expected_robot_cost)}};
}

// [{"action", "in": "both" | first_name | second_name}]
json diff_json(const std::vector<std::string> &first, const std::vector<std::string> &second,
               const char *first_name, const char *second_name) {
    json out = json::array();
    for (const auto &step : plan_diff(first, second))
        out.push_back({{"action", step.action},
                       {"in", step.side == DiffSide::BOTH         ? "both"
                              : step.side == DiffSide::ONLY_FIRST ? first_name
                                                                  : second_name}});
    return out;
}

json task_explanation_json(const envdesign::task_explanation_t &t,
                           const envdesign::task_result_t &chosen) {
    json out = {{"name", t.name},
                {"baseline", t.has_baseline ? task_json(t.baseline) : json()},
                {"chosen", task_json(chosen)},
                {"explicable_plan", chosen.plan},
                {"robot_plan", t.has_robot_plan ? json(t.robot_plan) : json()},
                {"robot_optimal_cost",
                 t.has_robot_optimal_cost ? json_number(t.robot_optimal_cost) : json()},
                {"expected_plan", t.has_expected_plan ? json(t.expected_plan) : json()}};
    out["explicable_vs_robot"] =
        t.has_robot_plan ? diff_json(chosen.plan, t.robot_plan, "explicable", "robot") : json();
    out["explicable_vs_expected"] =
        t.has_expected_plan ? diff_json(chosen.plan, t.expected_plan, "explicable", "expected")
                            : json();
    return out;
}

json crossing_json(const envdesign::crossing_t &c) {
    if (!c.found)
        return nullptr;
    return {{"at", json_number(c.at)}, {"rival", point_json(c.rival)}};
}

json explanation_json(const envdesign::design_result_t &r) {
    const envdesign::explanation_t &e = r.explanation;
    json tasks = json::array();
    for (std::size_t i = 0; i < e.tasks.size() && i < r.tasks.size(); ++i)
        tasks.push_back(task_explanation_json(e.tasks[i], r.tasks[i]));
    json marginal = json::array();
    for (const auto &m : e.marginal)
        marginal.push_back(
            {{"modification", m.modification},
             {"evaluated", m.evaluated != 0},
             {"objective_without", m.evaluated ? json_number(m.without.terms.objective) : json()},
             {"value",
              m.evaluated ? json_number(m.without.terms.objective - r.best.objective) : json()},
             {"without", m.evaluated ? point_json(m.without) : json()}});
    const envdesign::break_even_t &b = e.break_even;
    json break_even = {{"horizon_down", crossing_json(b.horizon_down)},
                       {"horizon_up", crossing_json(b.horizon_up)},
                       {"horizon_limit", b.horizon_limit},
                       {"alpha_down", crossing_json(b.alpha_down)},
                       {"alpha_up", crossing_json(b.alpha_up)},
                       {"designs_compared", b.designs_compared}};
    return {{"discounted_horizon", json_number(e.discounted_horizon)},
            {"least_ie", json_number(e.least_ie)},
            {"expected_ie", json_number(e.chosen.expected_ie)},
            {"expected_robot_cost", json_number(e.chosen.expected_robot_cost)},
            {"tasks", tasks},
            {"marginal", marginal},
            {"break_even", break_even}};
}

// `cluster`: the counters only a coordinator fills.
void put_counters(json &out, const envdesign::design_counters_t &c, bool cluster) {
    out["configurations_evaluated"] = c.configurations_evaluated;
    out["planner_runs"] = c.planner_runs;
    out["seconds"] = c.seconds;
    out["configurations_total"] = c.configurations_total;
    out["configurations_abandoned"] = c.configurations_abandoned;
    out["configurations_skipped"] = c.configurations_skipped;
    out["configurations_pruned"] = c.configurations_pruned;
    out["tasks_inherited"] = c.tasks_inherited;
    out["configurations_probed"] = c.configurations_probed;
    out["task_evaluations"] = c.task_evaluations;
    out["cache_hits"] = c.cache_hits;
    out["groundings_skipped"] = c.groundings_skipped;
    out["planner_seconds"] = c.planner_seconds;
    if (cluster)
        out["cluster"] = {{"jobs_sent", c.jobs_sent},
                          {"jobs_resent", c.jobs_resent},
                          {"duplicates_ignored", c.duplicates_ignored},
                          {"planners_used", c.planners_used},
                          {"transport_seconds", c.transport_seconds},
                          {"job_seconds", c.job_seconds},
                          {"stored_answers", c.stored_answers}};
}

void put_explanation(json &out, const envdesign::design_result_t &r) {
    const envdesign::explanation_t &e = r.explanation;
    out["weights"] = {{"alpha", e.alpha}, {"beta", e.beta},       {"kappa", e.kappa},
                      {"gamma", e.gamma}, {"horizon", e.horizon}, {"distance", e.distance}};
    out["weighted_terms"] = weighted_json(r.best, e, explaining(r));
    out["least_inexplicability"] = json_number(e.least_inexplicability);
    out["explanation"] = explanation_json(r);
    // Beside SPEC.md's "baseline", not in it: clients that print SPEC.md's fields (the
    // Python client) stay equal to this one.
    if (r.has_baseline)
        out["explanation"]["baseline_weighted_terms"] = weighted_json(r.baseline, e, explaining(r));
}

} // namespace

json result_json_value(const envdesign::design_result_t &r) {
    json out;
    out["status"] = r.status;
    if (r.status == "unsolvable")
        out["reason"] = r.error;
    if (r.has_design) {
        out["design"] = r.design;
        out.update(objective_json(r.best, explaining(r)));
        out["tasks"] = json::array();
        for (const auto &t : r.tasks)
            out["tasks"].push_back(task_json(t));
    } else {
        out["design"] = nullptr;
        out["objective"] = nullptr;
        out["terms"] = nullptr;
        out["tasks"] = json::array();
    }
    out["baseline"] = r.has_baseline ? objective_json(r.baseline, explaining(r)) : json();
    put_counters(out, r.counters, !r.sender.empty()); // a coordinator sent it
    out["limit_reached"] = r.limit_reached != 0;
    if (r.has_gap)
        out["gap"] = json_number(r.gap);
    out["notes"] = r.notes;
    if (!r.change.empty()) // a re-evaluation: what changed and why
        out["change"] = r.change;
    if (r.has_design && r.has_explanation)
        put_explanation(out, r);
    if (r.ranking_size > 0) {
        out["ranking"] = json::array();
        for (const auto &p : r.ranking)
            out["ranking"].push_back(point_json(p));
    }
    if (!r.warnings.empty()) // what the user should read beside the answer
        out["warnings"] = r.warnings;
    return out;
}

std::string result_json(const envdesign::design_result_t &r) {
    return json_text(result_json_value(r));
}

} // namespace envdesign::client
