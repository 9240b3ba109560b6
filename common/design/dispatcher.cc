#include "design/dispatcher.h"

namespace envdesign::design {

Dispatcher::Dispatcher(const std::vector<Configuration> &batch, int tasks, bool robot_bounds,
                       const EvaluationCallbacks &callbacks)
    : callbacks_(callbacks), tasks_(tasks), robot_bounds_(robot_bounds), progress_(batch.size()) {
    for (const auto &c : batch)
        state_.push_back({c, EvaluationStatus::LIMIT,
                          std::vector<std::optional<TaskExplicability>>(tasks),
                          std::vector<std::optional<double>>(tasks)});
    if (!robot_bounds_)
        for (auto &p : progress_)
            p.bounds_sent = p.bounds_known = tasks;
}

std::optional<Job> Dispatcher::next_job() {
    for (int c = first_open_; c < static_cast<int>(state_.size()); ++c) {
        if (auto job = next_job_of(c))
            return job;
        const Progress &p = progress_[c];
        if (c == first_open_ && (p.stopped || p.tasks_sent == tasks_))
            ++first_open_; // nothing more to send for it
    }
    return std::nullopt;
}

std::optional<Job> Dispatcher::next_job_of(int c) {
    Progress &p = progress_[c];
    if (p.stopped)
        return std::nullopt;
    if (p.bounds_sent < tasks_) {
        ++p.in_flight;
        return Job{c, p.bounds_sent++, JobKind::ROBOT_BOUND};
    }
    if (p.bounds_known < tasks_ || p.tasks_sent == tasks_)
        return std::nullopt; // waiting for answers
    if (abandon(c)) {
        stop(c, EvaluationStatus::CUT_OFF);
        finish_if_idle(c);
        return std::nullopt;
    }
    ++p.in_flight;
    return Job{c, p.tasks_sent++, JobKind::EXPLICABILITY};
}

void Dispatcher::receive(JobAnswer a) {
    int c = a.job.configuration;
    Progress &p = progress_[c];
    --p.in_flight;
    if (a.job.kind == JobKind::ROBOT_BOUND) {
        ++p.bounds_known;
        state_[c].robot_cost_bounds[a.job.task] = a.robot_bound;
    } else if (a.explicability.status == ExplicabilityStatus::LIMIT) {
        stop(c, EvaluationStatus::LIMIT);
    } else {
        state_[c].tasks[a.job.task] = std::move(a.explicability);
    }
    if (!p.stopped && complete(c))
        stop(c, EvaluationStatus::COMPLETE);
    else if (!p.stopped && p.bounds_known == tasks_ && abandon(c))
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
