#include "design/evaluation/dispatcher.h"

#include "design/behaviour/explicability.h"

#include <cmath>

namespace envdesign::design {

bool asks_robot_bounds(const DesignProblem &problem) {
    return problem.weights.kappa > 0 || ie_floors_hold(problem);
}

Dispatcher::Dispatcher(const std::vector<ConfigurationEvaluation> &batch, int tasks,
                       bool robot_bounds, bool ie_floors, const EvaluationCallbacks &callbacks,
                       bool exact_bounds_first)
    : callbacks_(callbacks), robot_bounds_(robot_bounds), state_(batch), progress_(batch.size()) {
    for (std::size_t c = 0; c < state_.size(); ++c) {
        ConfigurationEvaluation &e = state_[c];
        e.status = EvaluationStatus::LIMIT;
        e.tasks.resize(tasks);
        e.robot_cost_bounds.resize(tasks);
        e.ie_floors.resize(tasks);
        e.explanation_floors.resize(tasks);
        for (int t = 0; t < tasks; ++t) {
            if (e.tasks[t])
                continue;
            progress_[c].tasks_needed.push_back(t);
            const auto &given = e.robot_cost_bounds[t];
            bool floor_needed = ie_floors && given && std::isfinite(*given) && !e.ie_floors[t];
            if (robot_bounds_ && (!given || floor_needed))
                progress_[c].bounds_needed.push_back(t);
            if (robot_bounds_ && given && exact_bounds_first)
                progress_[c].exact_needed.push_back(t);
        }
    }
}

std::optional<Job> Dispatcher::next_job() {
    for (int c = first_open_; c < static_cast<int>(state_.size()); ++c) {
        if (auto job = next_job_of(c))
            return job;
        const Progress &p = progress_[c];
        if (c == first_open_ && (p.stopped || p.tasks_sent == needed(p)))
            ++first_open_; // nothing more to send for it
    }
    return std::nullopt;
}

std::optional<Job> Dispatcher::next_job_of(int c) {
    Progress &p = progress_[c];
    if (p.stopped)
        return std::nullopt;
    if (needed(p) == 0) { // everything was known
        stop(c, EvaluationStatus::COMPLETE);
        finish_if_idle(c);
        return std::nullopt;
    }
    int bounds = static_cast<int>(p.bounds_needed.size());
    if (p.bounds_sent < bounds) {
        ++p.in_flight;
        int task = p.bounds_needed[p.bounds_sent++];
        return Job{c, task, JobKind::ROBOT_BOUND, state_[c].robot_cost_bounds[task]};
    }
    if (p.bounds_known < bounds || p.tasks_sent == needed(p))
        return std::nullopt; // waiting for answers
    int exact = static_cast<int>(p.exact_needed.size());
    if (p.exact_known < exact) {
        if (p.exact_sent == 0 && abandon(c)) {
            stop(c, EvaluationStatus::CUT_OFF);
            finish_if_idle(c);
            return std::nullopt;
        }
        if (p.exact_sent == exact)
            return std::nullopt; // waiting for answers
        ++p.in_flight;
        return Job{c, p.exact_needed[p.exact_sent++], JobKind::ROBOT_BOUND, std::nullopt};
    }
    if (abandon(c)) {
        stop(c, EvaluationStatus::CUT_OFF);
        finish_if_idle(c);
        return std::nullopt;
    }
    ++p.in_flight;
    return Job{c, p.tasks_needed[p.tasks_sent++], JobKind::EXPLICABILITY, std::nullopt};
}

int Dispatcher::needed(const Progress &p) { return static_cast<int>(p.tasks_needed.size()); }

void Dispatcher::receive(JobAnswer a) {
    int c = a.job.configuration;
    Progress &p = progress_[c];
    --p.in_flight;
    if (a.job.kind == JobKind::ROBOT_BOUND) {
        // Exact bounds are asked only once every first bound is back.
        bool exact = p.exact_sent > 0;
        ++(exact ? p.exact_known : p.bounds_known);
        if (a.robot_bound) // else keep a given one
            state_[c].robot_cost_bounds[a.job.task] = a.robot_bound;
        if (a.ie_floor || !exact) { // an exact bound's floor replaces the one it raises
            state_[c].ie_floors[a.job.task] = a.ie_floor;
            state_[c].explanation_floors[a.job.task] = a.explanation_floor;
        }
    } else if (a.explicability.status == ExplicabilityStatus::LIMIT) {
        stop(c, EvaluationStatus::LIMIT);
    } else {
        state_[c].tasks[a.job.task] = std::move(a.explicability);
    }
    if (!p.stopped && complete(c))
        stop(c, EvaluationStatus::COMPLETE);
    else if (!p.stopped && abandon(c)) // every answer may raise the bound, a bound's too
        stop(c, EvaluationStatus::CUT_OFF);
    finish_if_idle(c);
}

void Dispatcher::finish_rest() {
    for (int c = 0; c < static_cast<int>(state_.size()); ++c) {
        stop(c, EvaluationStatus::LIMIT);
        finish_if_idle(c);
    }
}

bool Dispatcher::complete(int c) const {
    for (const auto &t : state_[c].tasks)
        if (!t)
            return false;
    return true;
}

bool Dispatcher::abandon(int c) { return callbacks_.abandon && callbacks_.abandon(state_[c]); }

void Dispatcher::stop(int c, EvaluationStatus status) {
    if (!progress_[c].stopped)
        progress_[c].stopped = status;
}

void Dispatcher::finish_if_idle(int c) {
    Progress &p = progress_[c];
    if (p.finished || !p.stopped || p.in_flight > 0)
        return;
    p.finished = true;
    state_[c].status = *p.stopped;
    callbacks_.done(std::move(state_[c]));
}

} // namespace envdesign::design
