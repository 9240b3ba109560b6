#include "bridge/messages.h"

#include <set>

namespace envdesign::bridge {
namespace {

using envdesign::task_distribution_t;

std::int8_t state_code(arrivals::DriftState state) {
    switch (state) {
    case arrivals::DriftState::PENDING:
        return task_distribution_t::STATE_PENDING;
    case arrivals::DriftState::HELD:
        return task_distribution_t::STATE_HELD;
    default:
        return task_distribution_t::STATE_ARMED;
    }
}

std::int8_t reason_code(arrivals::Reason reason) {
    switch (reason) {
    case arrivals::Reason::INITIAL:
        return task_distribution_t::REASON_INITIAL;
    case arrivals::Reason::NEW_TASK:
        return task_distribution_t::REASON_NEW_TASK;
    case arrivals::Reason::DRIFT:
    case arrivals::Reason::REWEIGH: // the estimate moved; no message of its own
    case arrivals::Reason::UNEVALUATED:
        return task_distribution_t::REASON_DRIFT;
    }
    return task_distribution_t::REASON_NONE;
}

double at(const arrivals::Distribution &d, const std::string &task) {
    auto it = d.find(task);
    return it == d.end() ? 0.0 : it->second;
}

void put_tasks(task_distribution_t &m, const arrivals::Distribution &estimate,
               const arrivals::Distribution &reference) {
    std::set<std::string> names;
    for (const auto &[task, p] : estimate)
        names.insert(task);
    for (const auto &[task, p] : reference)
        names.insert(task);
    for (const auto &task : names) {
        m.tasks.push_back(task);
        m.probabilities.push_back(at(estimate, task));
        m.reference.push_back(at(reference, task));
    }
    m.num_tasks = static_cast<std::int16_t>(m.tasks.size());
    m.distance = arrivals::total_variation(reference, estimate);
}

void put_counters(task_distribution_t &m, const arrivals::ProblemStatus &status,
                  const arrivals::IntakeCounters &counters) {
    m.received = counters.received;
    m.accepted = counters.count(arrivals::Verdict::ACCEPTED);
    m.estimated = status.estimated;
    m.unknown_task = status.unknown_task;
    m.sequence_gaps = counters.sequence_gaps;
    m.sequence_unseen = counters.sequence_unseen;
    for (int v = 1; v < arrivals::VERDICTS; ++v) {
        m.rejected_kinds.push_back(arrivals::to_string(static_cast<arrivals::Verdict>(v)));
        m.rejected_counts.push_back(counters.by_verdict[v]);
    }
    m.num_rejected = static_cast<std::int16_t>(m.rejected_kinds.size());
}

} // namespace

task_distribution_t distribution_message(const arrivals::ProblemStatus &status,
                                         const arrivals::IntakeCounters &counters,
                                         const arrivals::TrackerConfig &config,
                                         const DesignInForce &design) {
    task_distribution_t m{};
    m.request_id = design.request_id;
    m.problem_id = status.problem_id;
    m.estimator = arrivals::to_string(config.estimator);
    m.samples = status.samples;
    put_tasks(m, status.estimate, status.reference);
    m.threshold = config.drift.threshold;
    m.state = state_code(status.state);
    m.reason = task_distribution_t::REASON_NONE;
    put_counters(m, status, counters);
    m.design = design.design;
    m.design_size = static_cast<std::int16_t>(m.design.size());
    m.objective = design.objective;
    m.last_change = design.last_change;
    return m;
}

task_distribution_t request_message(const arrivals::Request &request,
                                    const arrivals::ProblemStatus &status,
                                    const arrivals::IntakeCounters &counters,
                                    const arrivals::TrackerConfig &config,
                                    const DesignInForce &design) {
    task_distribution_t m = distribution_message(status, counters, config, design);
    m.tasks.clear();
    m.probabilities.clear();
    m.reference.clear();
    put_tasks(m, request.estimate, request.reference);
    m.samples = request.samples;
    m.reason = reason_code(request.reason);
    for (const auto &task : request.new_tasks) {
        m.new_tasks.push_back(task.name);
        m.new_task_problems.push_back(task.problem);
        m.new_task_human_problems.push_back(task.human_problem);
    }
    m.num_new_tasks = static_cast<std::int16_t>(m.new_tasks.size());
    return m;
}

arrivals::Distribution distribution_of(const envdesign::design_result_t &result) {
    arrivals::Distribution d;
    if (!result.has_design)
        return d;
    for (const auto &task : result.tasks)
        d[task.name] = task.probability;
    return d;
}

} // namespace envdesign::bridge
