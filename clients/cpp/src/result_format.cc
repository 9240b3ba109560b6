#include "result_format.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace envdesign::client {
namespace {

using nlohmann::json;

// As the engine writes numbers: integral values as integers, infinity as "inf".
json number(double value) {
    if (std::isinf(value))
        return "inf";
    if (value == std::floor(value) && std::abs(value) < 1e15)
        return static_cast<long long>(value);
    return value;
}

// robot_behaviour EXPLAINING: the tasks carry their explaining option.
bool explaining(const envdesign::design_result_t &r) {
    for (const auto &t : r.tasks)
        if (t.has_explanation)
            return true;
    return false;
}

json objective_json(const envdesign::design_terms_t &t, bool explaining) {
    json out = {{"objective", number(t.objective)},
                {"terms",
                 {{"inexplicability", number(t.inexplicability)},
                  {"design_cost", number(t.design_cost)},
                  {"robot_cost", number(t.robot_cost)}}}};
    if (explaining)
        out["terms"]["explanation"] = number(t.explanation);
    return out;
}

// As design/result_json.cc: the option taken and both options' key values.
void put_option(const envdesign::task_result_t &t, json &task) {
    if (!t.has_explanation)
        return;
    task["option"] = t.explained ? "explain" : "act_explicably";
    task["explanation"] = t.explanation.found ? json(t.explanation.differences) : json();
    task["explicable_ie"] = number(t.explicable_ie);
    task["robot_optimal_cost"] = number(t.explanation.robot_optimal_cost);
}

json tasks_json(const envdesign::design_result_t &r) {
    json tasks = json::array();
    for (const auto &t : r.tasks) {
        json task = {{"name", t.name},
                     {"probability", t.probability},
                     {"ie", number(t.ie)},
                     {"robot_cost", number(t.robot_cost)},
                     {"human_plan_cost", number(t.human_plan_cost)},
                     {"human_optimal_cost",
                      t.has_human_optimal_cost ? number(t.human_optimal_cost) : json()},
                     {"plan", t.plan}};
        put_option(t, task);
        tasks.push_back(std::move(task));
    }
    return tasks;
}

void put_counters(json &out, const envdesign::design_counters_t &c) {
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
    out["cluster"] = {{"jobs_sent", c.jobs_sent},
                      {"jobs_resent", c.jobs_resent},
                      {"duplicates_ignored", c.duplicates_ignored},
                      {"planners_used", c.planners_used},
                      {"transport_seconds", c.transport_seconds},
                      {"job_seconds", c.job_seconds},
                      {"stored_answers", c.stored_answers}};
}

std::string shown(double value) { return number(value).dump(); }

void terms_line(std::ostream &out, const char *label, const envdesign::design_terms_t &t) {
    out << label << shown(t.objective) << " (inexplicability " << shown(t.inexplicability)
        << ", design cost " << shown(t.design_cost) << ", robot cost " << shown(t.robot_cost);
    if (t.explanation != 0)
        out << ", explanation " << shown(t.explanation);
    out << ")\n";
}

// "  explains: +init (a), -pre move (b)" or "  acts explicably (explanation: ...)".
void explanation_line(std::ostream &out, const envdesign::task_result_t &t) {
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

} // namespace

std::string result_json(const envdesign::design_result_t &r) {
    json out;
    out["status"] = r.status;
    if (r.has_design) {
        out["design"] = r.design;
        out.update(objective_json(r.best, explaining(r)));
        out["tasks"] = tasks_json(r);
    } else {
        out["design"] = nullptr;
        out["objective"] = nullptr;
        out["terms"] = nullptr;
        out["tasks"] = json::array();
    }
    out["baseline"] = r.has_baseline ? objective_json(r.baseline, explaining(r)) : json();
    put_counters(out, r.counters);
    out["limit_reached"] = r.limit_reached != 0;
    if (r.has_gap)
        out["gap"] = number(r.gap);
    out["notes"] = r.notes;
    if (!r.change.empty()) // a re-evaluation: what changed and why
        out["change"] = r.change;
    // Names are bytes from the client's files: not UTF-8 ones become U+FFFD, as in the engine's
    // JSON (design/result_json.h), instead of making dump() throw.
    return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string result_text(const envdesign::design_result_t &r) {
    std::ostringstream out;
    out << "status: " << r.status << "\n";
    if (!r.has_design) {
        out << "no configuration was evaluated in time\n";
        return out.str();
    }
    out << "design: {";
    for (std::size_t i = 0; i < r.design.size(); ++i)
        out << (i ? ", " : "") << r.design[i];
    out << "}\n";
    terms_line(out, "objective: ", r.best);
    if (r.has_baseline)
        terms_line(out, "baseline: ", r.baseline);
    for (const auto &t : r.tasks) {
        out << "task " << t.name << ": ie " << shown(t.ie) << ", robot cost " << shown(t.robot_cost)
            << ", plan";
        for (const auto &step : t.plan)
            out << " " << step;
        out << "\n";
        if (t.has_explanation)
            explanation_line(out, t);
    }
    if (r.has_gap)
        out << "proven gap: " << shown(r.gap) << "\n";
    for (const auto &note : r.notes)
        out << "note: " << note << "\n";
    return out.str();
}

} // namespace envdesign::client
