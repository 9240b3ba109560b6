#include "arrivals/drift_detector.h"

namespace envdesign::arrivals {

DriftDetector::DriftDetector(DriftConfig config, Distribution reference)
    : config_(config), reference_(std::move(reference)) {}

bool DriftDetector::observe(const Distribution &estimate, double samples, double now) {
    ++arrivals_since_request_;
    return recheck(estimate, samples, now);
}

bool DriftDetector::recheck(const Distribution &estimate, double samples, double now) {
    last_tv_ = total_variation(reference_, estimate);
    if (state_ == DriftState::PENDING) {
        if (now - requested_at_ < config_.answer_timeout_s)
            return false;
        ++timeouts_;
        state_ = DriftState::ARMED;
        requested_before_ = false; // no answer came: the hold-off after it does not apply
    }
    if (state_ == DriftState::HELD && last_tv_ < config_.rearm_threshold)
        state_ = DriftState::ARMED;
    bool drifted = samples >= config_.min_samples && last_tv_ >= config_.threshold &&
                   (!requested_before_ || arrivals_since_request_ >= config_.holdoff_arrivals);
    if (!drifted)
        return false;
    if (state_ == DriftState::HELD && now - requested_at_ < config_.retry_s)
        return false;
    return request(now, estimate);
}

bool DriftDetector::force(double now, const Distribution &requested) {
    return state_ != DriftState::PENDING && request(now, requested);
}

bool DriftDetector::request(double now, const Distribution &requested) {
    state_ = DriftState::PENDING;
    requested_ = requested;
    requested_at_ = now;
    arrivals_since_request_ = 0;
    requested_before_ = true;
    ++requests_;
    return true;
}

void DriftDetector::answered(const Distribution &reference, const Distribution &estimate) {
    bool as_requested = state_ == DriftState::PENDING &&
                        total_variation(reference, requested_) < config_.rearm_threshold;
    reference_ = reference;
    last_tv_ = total_variation(reference_, estimate);
    // With no arrivals yet there is nothing the design could have missed.
    bool close = estimate.empty() || last_tv_ < config_.rearm_threshold;
    state_ = as_requested || close ? DriftState::ARMED : DriftState::HELD;
}

void DriftDetector::rebase(const Distribution &reference, const Distribution &estimate) {
    reference_ = reference;
    last_tv_ = total_variation(reference_, estimate);
    if (state_ == DriftState::HELD && last_tv_ < config_.rearm_threshold)
        state_ = DriftState::ARMED;
}

const char *to_string(DriftState state) {
    switch (state) {
    case DriftState::ARMED:
        return "armed";
    case DriftState::PENDING:
        return "pending";
    case DriftState::HELD:
        return "held";
    }
    return "?";
}

} // namespace envdesign::arrivals
