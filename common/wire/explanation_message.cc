#include "wire/explanation_message.h"

#include "design/behaviour/behaviour.h"
#include "wire/model_explanation_message.h"

namespace envdesign::wire {
namespace {

std::int16_t length(std::size_t size) { return static_cast<std::int16_t>(size); }

envdesign::crossing_t crossing_message(const design::DesignProblem &problem,
                                       const std::optional<design::Crossing> &crossing) {
    envdesign::crossing_t m{};
    m.found = crossing.has_value();
    m.at = crossing ? crossing->at : 0;
    m.rival = point_message(problem, crossing ? crossing->rival : design::DesignPoint{});
    return m;
}

envdesign::break_even_t break_even_message(const design::DesignProblem &problem,
                                           const design::BreakEven &b) {
    envdesign::break_even_t m{};
    m.horizon_down = crossing_message(problem, b.horizon_down);
    m.horizon_up = crossing_message(problem, b.horizon_up);
    m.horizon_limit = b.horizon_limit;
    m.alpha_down = crossing_message(problem, b.alpha_down);
    m.alpha_up = crossing_message(problem, b.alpha_up);
    m.designs_compared = b.designs_compared;
    return m;
}

envdesign::task_explanation_t task_explanation_message(const design::DesignProblem &problem, int i,
                                                       const design::TaskComparison &t) {
    envdesign::task_explanation_t m{};
    m.name = problem.tasks[i].name;
    m.has_baseline = t.baseline.status != design::ExplicabilityStatus::LIMIT;
    m.baseline = task_message(problem, i, t.baseline);
    m.has_robot_plan = t.robot_plan.has_value();
    m.robot_plan = t.robot_plan.value_or(std::vector<std::string>{});
    m.robot_plan_length = length(m.robot_plan.size());
    m.has_robot_optimal_cost = t.robot_optimal_cost.has_value();
    m.robot_optimal_cost = t.robot_optimal_cost.value_or(design::INF);
    m.has_expected_plan = t.expected_plan.has_value();
    m.expected_plan = t.expected_plan.value_or(std::vector<std::string>{});
    m.expected_plan_length = length(m.expected_plan.size());
    return m;
}

const char *distance_name(design::Distance distance) {
    return distance == design::Distance::COST_DIFF ? "COST_DIFF" : "EXP_COST_DIFF";
}

} // namespace

envdesign::design_terms_t terms_message(const design::Objective &objective) {
    envdesign::design_terms_t t;
    t.objective = objective.value;
    t.inexplicability = objective.terms.inexplicability;
    t.design_cost = objective.terms.design_cost;
    t.robot_cost = objective.terms.robot_cost;
    t.explanation = objective.terms.explanation;
    return t;
}

envdesign::task_result_t task_message(const design::DesignProblem &problem, int i,
                                      const design::TaskExplicability &t) {
    const design::DesignTask &task = problem.tasks[i];
    envdesign::task_result_t m;
    m.name = task.name;
    m.probability = task.probability;
    put_costs_and_plan(t, m);
    put_option(problem.weights, t, m); // EXPLAINING: the option the robot takes
    return m;
}

envdesign::design_point_t point_message(const design::DesignProblem &problem,
                                        const design::DesignPoint &point) {
    envdesign::design_point_t m{};
    m.design = design::design_names(problem, point.configuration);
    m.design_size = length(m.design.size());
    m.design_cost = point.design_cost;
    m.expected_ie = point.expected_ie;
    m.expected_robot_cost = point.expected_robot_cost;
    m.terms = terms_message(design::objective_at(problem.weights, point));
    return m;
}

envdesign::explanation_t explanation_message(const design::DesignProblem &problem,
                                             const design::DesignExplanation &e) {
    envdesign::explanation_t m{};
    m.alpha = e.weights.alpha;
    m.beta = e.weights.beta;
    m.kappa = e.weights.kappa;
    m.gamma = e.weights.gamma;
    m.horizon = e.weights.horizon;
    m.distance = distance_name(e.weights.distance);
    m.robot_behaviour = design::behaviour_of(e.weights.behaviour).name;
    m.discounted_horizon = e.discounted_horizon;
    m.least_ie = e.least_ie;
    m.least_inexplicability = e.least_inexplicability;
    m.chosen = point_message(problem, e.chosen);
    for (std::size_t i = 0; i < e.tasks.size() && i < problem.tasks.size(); ++i)
        m.tasks.push_back(task_explanation_message(problem, static_cast<int>(i), e.tasks[i]));
    m.num_tasks = length(m.tasks.size());
    for (const auto &v : e.marginal) {
        envdesign::marginal_value_t value{};
        value.modification = problem.modifications[v.modification].name;
        value.evaluated = v.without.has_value();
        value.without = point_message(problem, v.without.value_or(design::DesignPoint{}));
        m.marginal.push_back(std::move(value));
    }
    m.num_marginal = length(m.marginal.size());
    m.break_even = break_even_message(problem, e.break_even);
    return m;
}

envdesign::explanation_t empty_explanation() {
    envdesign::explanation_t m{};
    m.distance = "EXP_COST_DIFF";
    m.robot_behaviour = "EXPLICABLE";
    return m;
}

} // namespace envdesign::wire
