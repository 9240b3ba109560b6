#pragma once
// The estimate of one design problem's task distribution D from its arrivals.
//
// Two estimators, chosen by configuration:
//   - WINDOW n: the frequencies of the tasks among the last n arrivals (every arrival in the
//     window weighs 1, older ones 0);
//   - DECAY h: exponential decay, an arrival's weight halves with every h later arrivals
//     (lambda = 2^(-1/h) per arrival); the effective sample size tends to 1 / (1 - lambda),
//     about 1.44 h.
// Both count arrivals, not seconds: D is the mix of tasks, not their rate, so a busy hour
// and a quiet one weigh the same number of recent tasks. effective_samples() says how much
// evidence is behind the estimate (the window's fill, or the sum of the decayed weights).
//
// Example:
//   DistributionEstimator e(parse_estimator_config("window:4"));
//   for (auto t : {"a", "a", "b", "a"}) e.add(t);
//   e.estimate();  // {a: 0.75, b: 0.25}

#include "arrivals/distribution.h"

#include <deque>
#include <string>

namespace envdesign::arrivals {

struct EstimatorConfig {
    enum class Kind { WINDOW, DECAY };
    Kind kind = Kind::WINDOW;
    int window = 200;       // WINDOW: arrivals kept, >= 1
    double half_life = 100; // DECAY: arrivals after which a weight has halved, > 0
};

// "window:N" or "decay:H" (H may be fractional); throws std::invalid_argument otherwise.
EstimatorConfig parse_estimator_config(const std::string &text);
// The inverse of parse_estimator_config: "window:200", "decay:100".
std::string to_string(const EstimatorConfig &config);

class DistributionEstimator {
public:
    explicit DistributionEstimator(EstimatorConfig config);

    void add(const std::string &task);
    Distribution estimate() const; // empty before the first arrival
    double effective_samples() const;
    const EstimatorConfig &config() const { return config_; }

private:
    EstimatorConfig config_;
    double lambda_ = 1; // DECAY: weight factor per arrival
    std::deque<std::string> window_;
    Distribution weights_; // WINDOW: counts in the window; DECAY: decayed weights
};

} // namespace envdesign::arrivals
