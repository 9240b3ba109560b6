#include "design/result_json.h"

#include "design/explaining.h"

#include <cmath>

namespace envdesign::design {
namespace {

std::string status_name(ExplicabilityStatus status) {
    switch (status) {
    case ExplicabilityStatus::SOLVED:
        return "solved";
    case ExplicabilityStatus::INEXPLICABLE:
        return "unsolvable";
    default:
        return "limit";
    }
}

bool explaining(const DesignProblem &problem) {
    return problem.weights.behaviour == RobotBehaviour::EXPLAINING;
}

nlohmann::json terms_json(const DesignProblem &problem, const ObjectiveTerms &terms) {
    nlohmann::json out = {{"inexplicability", json_number(terms.inexplicability)},
                          {"design_cost", json_number(terms.design_cost)},
                          {"robot_cost", json_number(terms.robot_cost)}};
    if (explaining(problem))
        out["explanation"] = json_number(terms.explanation);
    return out;
}

nlohmann::json objective_json(const DesignProblem &problem, const EvaluatedDesign &design) {
    return {{"objective", json_number(design.objective.value)},
            {"terms", terms_json(problem, design.objective.terms)}};
}

// EXPLAINING: the option taken sets ie, robot_cost and plan; both options are shown.
void put_option(const DesignProblem &problem, const TaskExplicability &t, nlohmann::json &task) {
    if (!explaining(problem) || !t.explanation)
        return;
    const TaskExplanation &x = *t.explanation;
    BehaviourChoice c = choose_behaviour(problem.weights, t);
    task["option"] = c.explained ? "explain" : "act_explicably";
    task["explanation"] = x.found ? nlohmann::json(x.differences) : nlohmann::json();
    task["explicable_ie"] = json_number(t.ie);
    task["robot_optimal_cost"] = json_number(x.robot_optimal_cost);
    if (c.explained) {
        task["ie"] = json_number(c.ie);
        task["robot_cost"] = json_number(c.robot_cost);
        task["plan"] = x.robot_plan;
    }
}

nlohmann::json tasks_json(const DesignProblem &problem, const EvaluatedDesign &design) {
    nlohmann::json tasks = nlohmann::json::array();
    for (std::size_t i = 0; i < design.tasks.size(); ++i) {
        const TaskExplicability &t = design.tasks[i];
        nlohmann::json task = {{"name", problem.tasks[i].name},
                               {"probability", problem.tasks[i].probability},
                               {"ie", json_number(t.ie)},
                               {"robot_cost", json_number(t.robot_cost)},
                               {"human_plan_cost", json_number(t.human_plan_cost)},
                               {"human_optimal_cost", json_number(t.human_optimal_cost)},
                               {"plan", t.plan}};
        put_option(problem, t, task);
        tasks.push_back(std::move(task));
    }
    return tasks;
}

} // namespace

std::string json_text(const nlohmann::json &value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json json_number(std::optional<double> value) {
    if (!value)
        return nullptr;
    if (std::isinf(*value))
        return "inf";
    if (*value == std::floor(*value) && std::abs(*value) < 1e15)
        return static_cast<long long>(*value);
    return *value;
}

nlohmann::json explicability_json(const TaskExplicability &r) {
    return {{"status", status_name(r.status)},
            {"plan", r.plan},
            {"ie", r.status == ExplicabilityStatus::LIMIT ? nlohmann::json() : json_number(r.ie)},
            {"robot_cost", json_number(r.robot_cost)},
            {"human_plan_cost", json_number(r.human_plan_cost)},
            {"human_optimal_cost", json_number(r.human_optimal_cost)}};
}

nlohmann::json design_json(const DesignProblem &problem, const DesignResult &result) {
    const DesignCounters &c = result.counters;
    nlohmann::json out;
    out["status"] = result.optimal ? "optimal" : "best_found";
    if (result.best) {
        out["design"] = design_names(problem, result.best->ranked.configuration);
        out.update(objective_json(problem, *result.best));
        out["tasks"] = tasks_json(problem, *result.best);
    } else {
        out["design"] = nullptr;
        out["objective"] = nullptr;
        out["terms"] = nullptr;
        out["tasks"] = nlohmann::json::array();
    }
    out["baseline"] =
        result.baseline ? objective_json(problem, *result.baseline) : nlohmann::json();
    if (!result.ranking.empty()) { // --ranking N: the N best, best first
        nlohmann::json ranking = nlohmann::json::array();
        for (const RankedDesign &d : result.ranking)
            ranking.push_back({{"design", design_names(problem, d.configuration)},
                               {"objective", json_number(d.objective)}});
        out["ranking"] = std::move(ranking);
    }
    out["configurations_evaluated"] = c.configurations_evaluated;
    out["planner_runs"] = c.evaluator.planner_runs;
    out["seconds"] = c.seconds;
    // Beyond SPEC.md's keys: where the work went and what the bounds saved.
    out["configurations_total"] = c.configurations_total;
    out["configurations_abandoned"] = c.configurations_abandoned;
    out["configurations_skipped"] = c.configurations_skipped;
    out["configurations_pruned"] = c.configurations_pruned;
    out["task_evaluations"] = c.evaluator.task_evaluations;
    out["cache_hits"] = c.evaluator.cache_hits;
    out["groundings_skipped"] = c.evaluator.groundings_skipped;
    out["planner_seconds"] = c.evaluator.planner_seconds;
    out["limit_reached"] = result.limit_reached;
    out["tasks_inherited"] = c.tasks_inherited;
    out["configurations_probed"] = c.configurations_probed;
    if (result.gap)
        out["gap"] = json_number(*result.gap);
    out["notes"] = result.notes;
    return out;
}

} // namespace envdesign::design
