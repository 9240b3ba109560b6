#include "arrivals/tracker.h"

#include <algorithm>
#include <cstdio>

namespace envdesign::arrivals {

const char *to_string(Reason reason) {
    switch (reason) {
    case Reason::INITIAL:
        return "initial";
    case Reason::NEW_TASK:
        return "new_task";
    case Reason::DRIFT:
        return "drift";
    case Reason::REWEIGH:
        return "reweigh";
    case Reason::UNEVALUATED:
        return "unevaluated";
    }
    return "?";
}

std::string describe(const Request &request) {
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, " (TV %.3f, %.0f samples)", request.distance,
                  request.samples);
    std::string text = std::string(to_string(request.reason)) + ": D " +
                       to_string(request.estimate) + " vs the design's " +
                       to_string(request.reference) + numbers;
    if (!request.new_tasks.empty()) {
        text += ", new task(s):";
        for (const auto &task : request.new_tasks)
            text += " " + task.name;
    }
    return text;
}

ArrivalTracker::ArrivalTracker(TrackerConfig config) : config_(config), intake_(config.intake) {}

void ArrivalTracker::add_problem(const std::string &id, const Distribution &reference) {
    Problem p{id,
              {},
              {},
              {},
              {},
              DistributionEstimator(config_.estimator),
              DriftDetector(config_.drift, reference),
              {}};
    for (const auto &[task, probability] : reference)
        p.tasks.insert(task);
    p.status.problem_id = id;
    p.status.reference = reference;
    problems_.insert_or_assign(id, std::move(p));
}

Request ArrivalTracker::initial_request(const std::string &id, double now) {
    Problem &p = problems_.at(id);
    p.detector.force(now, p.detector.reference());
    Request r = make_request(p, Reason::INITIAL);
    r.estimate = r.reference; // the spec's D, whatever arrived already
    r.distance = 0;
    return r;
}

Outcome ArrivalTracker::receive(const Arrival &arrival, double now, int64_t now_utime) {
    auto it = problems_.find(arrival.problem_id);
    Outcome out;
    out.verdict = intake_.check(arrival, it != problems_.end(), now, now_utime);
    out.clock_skewed = intake_.last_skewed();
    if (out.verdict != Verdict::ACCEPTED)
        return out;
    Problem &p = it->second;
    out.use = classify(p, arrival, now, out);
    if (out.use == Use::UNKNOWN_TASK)
        return out;
    p.estimator.add(arrival.task);
    ++p.status.estimated;
    Distribution estimate = p.estimator.estimate();
    bool drifted = p.detector.observe(estimate, p.estimator.effective_samples(), now);
    if (out.use == Use::NEW_TASK && !drifted && p.detector.state() != DriftState::PENDING)
        drifted = p.detector.force(now, estimate);
    if (drifted)
        out.request = make_request(p, out.use == Use::NEW_TASK ? Reason::NEW_TASK : Reason::DRIFT);
    return out;
}

// Whether the new-task bucket of `p` holds a token at `now` (refilled first); not taken.
bool ArrivalTracker::new_task_token(Problem &p, double now) {
    if (p.new_task_tokens < 0)
        p.new_task_tokens = config_.new_task_burst;
    else if (config_.new_task_interval_s > 0)
        p.new_task_tokens =
            std::min(config_.new_task_burst,
                     p.new_task_tokens + (now - p.new_task_at) / config_.new_task_interval_s);
    p.new_task_at = now;
    return p.new_task_tokens >= 1;
}

Use ArrivalTracker::classify(Problem &p, const Arrival &arrival, double now, Outcome &out) {
    const std::string &task = arrival.task;
    if (p.tasks.count(task) || p.proposed.count(task))
        return Use::ESTIMATED;
    bool admitted = static_cast<std::size_t>(p.status.new_tasks) < config_.max_new_tasks &&
                    new_task_token(p, now);
    out.held_back = !arrival.problem.empty() && !p.refused.count(task) && !admitted;
    if (out.held_back)
        ++p.status.new_tasks_held_back;
    if (arrival.problem.empty() || p.refused.count(task) || !admitted) {
        ++p.status.unknown_task;
        auto &names = p.status.unknown_task_names;
        auto it = names.find(task);
        // Beyond MAX_UNKNOWN_NAMES names a name is never remembered: not a first either.
        out.first_of_name = it == names.end() && names.size() < ProblemStatus::MAX_UNKNOWN_NAMES;
        if (it != names.end())
            ++it->second;
        else if (names.size() < ProblemStatus::MAX_UNKNOWN_NAMES)
            names.emplace(task, 1);
        return Use::UNKNOWN_TASK;
    }
    p.proposed[task] = {task, arrival.problem, arrival.human_problem};
    p.new_task_tokens -= 1;
    ++p.status.new_tasks;
    return Use::NEW_TASK;
}

Request ArrivalTracker::make_request(Problem &p, Reason reason) {
    Request r;
    r.problem_id = p.id;
    r.reason = reason;
    r.estimate = p.estimator.estimate();
    r.reference = p.detector.reference();
    r.distance = total_variation(r.reference, r.estimate);
    r.samples = p.estimator.effective_samples();
    for (const auto &[name, task] : p.proposed) {
        r.new_tasks.push_back(task);
        p.sent.insert(name);
    }
    return r;
}

std::optional<Request> ArrivalTracker::answered(const std::string &id,
                                                const Distribution &reference, double now) {
    auto it = problems_.find(id);
    if (it == problems_.end())
        return std::nullopt;
    Problem &p = it->second;
    p.designed = true;
    p.tasks.clear();
    for (const auto &[task, probability] : reference)
        p.tasks.insert(task);
    // A proposed task that was sent and is not in the answer was refused.
    for (auto t = p.proposed.begin(); t != p.proposed.end();) {
        bool done = p.tasks.count(t->first) || p.sent.count(t->first);
        if (done && !p.tasks.count(t->first)) {
            p.refused.insert(t->first);
            ++p.status.refused_tasks;
        }
        if (done)
            p.sent.erase(t->first);
        t = done ? p.proposed.erase(t) : std::next(t);
    }
    Distribution estimate = p.estimator.estimate();
    p.detector.answered(reference, estimate);
    if (p.proposed.empty() || !p.detector.force(now, estimate))
        return std::nullopt;
    return make_request(p, Reason::NEW_TASK);
}

std::vector<Request> ArrivalTracker::requests_due(double now) {
    std::vector<Request> due;
    for (auto &[id, p] : problems_) {
        bool was_pending = p.detector.state() == DriftState::PENDING;
        Distribution estimate = p.estimator.estimate();
        if (p.detector.recheck(estimate, p.estimator.effective_samples(), now))
            due.push_back(make_request(p, Reason::DRIFT));
        else if (was_pending && !p.designed && p.detector.state() != DriftState::PENDING)
            due.push_back(initial_request(id, now));
    }
    return due;
}

std::vector<Request> ArrivalTracker::reweighs_due(double now) {
    std::vector<Request> due;
    if (config_.reweigh_interval_s <= 0)
        return due;
    for (auto &[id, p] : problems_) {
        bool changed = p.status.estimated != p.reweighed_estimated;
        if (!changed || now - p.reweighed_at < config_.reweigh_interval_s ||
            p.detector.state() == DriftState::PENDING || !p.proposed.empty())
            continue;
        p.reweighed_estimated = p.status.estimated;
        p.reweighed_at = now;
        ++p.status.reweighs;
        due.push_back(make_request(p, Reason::REWEIGH));
    }
    return due;
}

void ArrivalTracker::reweighed(const std::string &id, const Distribution &reference) {
    auto it = problems_.find(id);
    if (it == problems_.end() || it->second.detector.state() == DriftState::PENDING)
        return;
    it->second.detector.rebase(reference, it->second.estimator.estimate());
}

std::optional<Request> ArrivalTracker::unevaluated(const std::string &id, double now) {
    auto it = problems_.find(id);
    if (it == problems_.end() || !it->second.proposed.empty() ||
        it->second.estimator.effective_samples() < config_.drift.min_samples ||
        !it->second.detector.force(now, it->second.estimator.estimate()))
        return std::nullopt;
    return make_request(it->second, Reason::UNEVALUATED);
}

std::optional<ProblemStatus> ArrivalTracker::status(const std::string &id) const {
    auto it = problems_.find(id);
    if (it == problems_.end())
        return std::nullopt;
    const Problem &p = it->second;
    ProblemStatus s = p.status;
    s.estimate = p.estimator.estimate();
    s.reference = p.detector.reference();
    s.samples = p.estimator.effective_samples();
    s.distance = total_variation(s.reference, s.estimate);
    s.state = p.detector.state();
    s.requests = p.detector.requests();
    s.timeouts = p.detector.timeouts();
    return s;
}

std::vector<std::string> ArrivalTracker::problem_ids() const {
    std::vector<std::string> ids;
    for (const auto &[id, p] : problems_)
        ids.push_back(id);
    return ids;
}

} // namespace envdesign::arrivals
