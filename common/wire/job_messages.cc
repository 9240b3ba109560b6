#include "wire/job_messages.h"

#include "bus/log.h"
#include "design/model/numbers.h"
#include "design/objective/objective.h"
#include "envdesign/design_request_t.hpp"
#include "wire/model_explanation_message.h"

#include <cmath>

namespace envdesign::wire {
namespace {

using envdesign::evaluation_t;

} // namespace

heuristics::HeuristicKind heuristic_kind(std::int8_t heuristic) {
    switch (heuristic) {
    case envdesign::design_request_t::HEURISTIC_HMAX:
        return heuristics::HeuristicKind::HMAX;
    case envdesign::design_request_t::HEURISTIC_BLIND:
        return heuristics::HeuristicKind::BLIND;
    default:
        return heuristics::HeuristicKind::LMCUT;
    }
}

envdesign::job_t job_message(const design::Job &job, const design::Configuration &configuration,
                             std::int64_t request_id, const std::string &spec_hash,
                             std::int8_t heuristic, const design::Deadline &deadline) {
    envdesign::job_t m{};
    m.request_id = request_id;
    m.spec_hash = spec_hash;
    m.kind = job.kind == design::JobKind::ROBOT_BOUND ? envdesign::job_t::KIND_ROBOT_BOUND
                                                      : envdesign::job_t::KIND_EXPLICABILITY;
    m.task = static_cast<std::int16_t>(job.task);
    m.modifications.assign(configuration.begin(), configuration.end());
    m.num_modifications = static_cast<std::int16_t>(m.modifications.size());
    m.heuristic = heuristic;
    m.time_limit_s = deadline.remaining_seconds();
    m.has_robot_bound = job.robot_bound.has_value();
    m.robot_bound = job.robot_bound.value_or(0);
    return m;
}

std::optional<std::string> job_problem(const envdesign::job_t &job,
                                       const design::DesignProblem &problem) {
    if (job.kind != envdesign::job_t::KIND_ROBOT_BOUND &&
        job.kind != envdesign::job_t::KIND_EXPLICABILITY)
        return "unknown job kind " + std::to_string(job.kind);
    if (job.task < 0 || job.task >= static_cast<int>(problem.tasks.size()))
        return "task index " + std::to_string(job.task) + " out of range";
    int previous = -1;
    for (int m : job.modifications) {
        if (m <= previous || m >= static_cast<int>(problem.modifications.size()))
            return "the configuration is not ascending modification indices in range";
        previous = m;
    }
    if (job.heuristic < envdesign::design_request_t::HEURISTIC_LMCUT ||
        job.heuristic > envdesign::design_request_t::HEURISTIC_BLIND)
        return "unknown heuristic " + std::to_string(job.heuristic);
    if (auto why = design::number_problem(job.time_limit_s, design::TIME_LIMIT_S))
        return "the time limit " + *why;
    if (job.has_robot_bound && job.kind != envdesign::job_t::KIND_ROBOT_BOUND)
        return "a robot bound on a job that is not KIND_ROBOT_BOUND";
    if (job.has_robot_bound && !design::valid_plan_cost(job.robot_bound))
        return "the robot bound is not a cost in [0, 2^31) or infinite";
    return std::nullopt;
}

design::Configuration configuration_of(const envdesign::job_t &job) {
    return design::Configuration(job.modifications.begin(), job.modifications.end());
}

design::Job job_of(const envdesign::job_t &job) {
    design::Job out{0, job.task,
                    job.kind == envdesign::job_t::KIND_ROBOT_BOUND ? design::JobKind::ROBOT_BOUND
                                                                   : design::JobKind::EXPLICABILITY,
                    std::nullopt};
    if (job.has_robot_bound)
        out.robot_bound = job.robot_bound;
    return out;
}

std::optional<std::string> evaluation_problem(const evaluation_t &e, std::int8_t kind) {
    if (e.kind != kind)
        return "the answer's kind differs from the job's";
    if (e.status < evaluation_t::STATUS_SOLVED || e.status > evaluation_t::STATUS_ERROR)
        return "unknown status " + std::to_string(e.status);
    if (kind == envdesign::job_t::KIND_ROBOT_BOUND) {
        if (e.has_robot_bound && !design::valid_plan_cost(e.robot_bound))
            return "the robot bound is not a cost in [0, 2^31) or infinite";
        if (e.has_ie_floor && !design::valid_ie(e.ie_floor))
            return "the IE floor is not a number >= 0";
        if (e.has_explanation_floor && !design::valid_explanation_floor(e.explanation_floor))
            return "the explanation floor is not a count in [0, 1048576]";
        return std::nullopt;
    }
    if (e.status != evaluation_t::STATUS_SOLVED && e.status != evaluation_t::STATUS_INEXPLICABLE)
        return std::nullopt;
    // The same check as a record read back from the store (design/model/numbers.h).
    return design::evaluation_problem(job_answer(design::Job{}, e).explicability);
}

namespace {

void put_explicability(const design::TaskExplicability &t, evaluation_t &e) {
    switch (t.status) {
    case design::ExplicabilityStatus::SOLVED:
        e.status = evaluation_t::STATUS_SOLVED;
        break;
    case design::ExplicabilityStatus::INEXPLICABLE:
        e.status = evaluation_t::STATUS_INEXPLICABLE;
        break;
    default:
        e.status = evaluation_t::STATUS_LIMIT;
    }
    put_costs_and_plan(t, e);
    e.has_human_plan = t.human_plan.has_value();
    if (t.human_plan)
        e.human_plan = *t.human_plan;
    e.human_plan_length = static_cast<std::int16_t>(e.human_plan.size());
    e.has_explanation = t.explanation.has_value();
    e.explanation = model_explanation_message(t.explanation.value_or(design::TaskExplanation{}));
    e.has_optimal_actions = t.optimal_actions.has_value();
    if (t.optimal_actions)
        e.optimal_actions = *t.optimal_actions;
    e.optimal_actions_length = static_cast<std::int32_t>(e.optimal_actions.size());
}

void put_robot_bound(const design::JobAnswer &a, evaluation_t &e) {
    e.status = a.robot_bound ? evaluation_t::STATUS_SOLVED : evaluation_t::STATUS_LIMIT;
    e.has_robot_bound = a.robot_bound.has_value();
    e.robot_bound = a.robot_bound.value_or(design::INF);
    e.has_ie_floor = a.robot_bound && a.ie_floor;
    e.ie_floor = e.has_ie_floor ? *a.ie_floor : 0;
    e.has_explanation_floor = e.has_ie_floor && a.explanation_floor;
    e.explanation_floor = e.has_explanation_floor ? *a.explanation_floor : 0;
}

} // namespace

void put_answer(const design::JobAnswer &answer, evaluation_t &e) {
    if (answer.job.kind == design::JobKind::ROBOT_BOUND)
        put_robot_bound(answer, e);
    else
        put_explicability(answer.explicability, e);
}

design::JobAnswer job_answer(const design::Job &job, const evaluation_t &e) {
    design::JobAnswer answer{job, std::nullopt, std::nullopt, {}};
    if (job.kind == design::JobKind::ROBOT_BOUND) {
        if (e.has_robot_bound)
            answer.robot_bound = e.robot_bound;
        if (e.has_robot_bound && e.has_ie_floor)
            answer.ie_floor = e.ie_floor;
        if (e.has_robot_bound && e.has_ie_floor && e.has_explanation_floor)
            answer.explanation_floor = e.explanation_floor;
        return answer;
    }
    design::TaskExplicability &t = answer.explicability;
    if (e.status == evaluation_t::STATUS_SOLVED)
        t.status = design::ExplicabilityStatus::SOLVED;
    else if (e.status == evaluation_t::STATUS_INEXPLICABLE)
        t.status = design::ExplicabilityStatus::INEXPLICABLE;
    else
        return answer; // LIMIT
    t.ie = e.ie;
    t.robot_cost = e.robot_cost;
    t.human_plan_cost = e.human_plan_cost;
    if (e.has_human_optimal_cost)
        t.human_optimal_cost = e.human_optimal_cost;
    t.plan = e.plan;
    if (e.has_human_plan)
        t.human_plan = e.human_plan;
    if (e.has_explanation)
        t.explanation = model_explanation_value(e.explanation);
    if (e.has_optimal_actions)
        t.optimal_actions = e.optimal_actions;
    return answer;
}

} // namespace envdesign::wire
