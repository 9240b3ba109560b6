#include "arrivals/estimator.h"

#include <cmath>
#include <stdexcept>

namespace envdesign::arrivals {
namespace {

// Weights below this are dropped, so that a task that stopped arriving leaves the estimate
// instead of lingering at 1e-300.
constexpr double NEGLIGIBLE_WEIGHT = 1e-12;

double parse_positive(const std::string &number, const std::string &text) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(number, &used);
    } catch (const std::exception &) {
        used = 0;
    }
    if (used != number.size() || !(value > 0) || !std::isfinite(value))
        throw std::invalid_argument("bad estimator '" + text +
                                    "': expected window:N or decay:H with a positive number");
    return value;
}

} // namespace

EstimatorConfig parse_estimator_config(const std::string &text) {
    auto colon = text.find(':');
    std::string kind = text.substr(0, colon);
    std::string number = colon == std::string::npos ? "" : text.substr(colon + 1);
    EstimatorConfig config;
    if (kind == "window") {
        double n = parse_positive(number, text);
        if (n != std::floor(n) || n > 1e7)
            throw std::invalid_argument("bad estimator '" + text +
                                        "': the window is a whole number of arrivals");
        config.kind = EstimatorConfig::Kind::WINDOW;
        config.window = static_cast<int>(n);
    } else if (kind == "decay") {
        config.kind = EstimatorConfig::Kind::DECAY;
        config.half_life = parse_positive(number, text);
    } else {
        throw std::invalid_argument("bad estimator '" + text + "': expected window:N or decay:H");
    }
    return config;
}

std::string to_string(const EstimatorConfig &config) {
    if (config.kind == EstimatorConfig::Kind::WINDOW)
        return "window:" + std::to_string(config.window);
    char number[32];
    std::snprintf(number, sizeof number, "%g", config.half_life);
    return std::string("decay:") + number;
}

DistributionEstimator::DistributionEstimator(EstimatorConfig config) : config_(config) {
    if (config_.kind == EstimatorConfig::Kind::DECAY)
        lambda_ = std::pow(2.0, -1.0 / config_.half_life);
}

void DistributionEstimator::add(const std::string &task) {
    if (config_.kind == EstimatorConfig::Kind::WINDOW) {
        window_.push_back(task);
        weights_[task] += 1;
        if (static_cast<int>(window_.size()) > config_.window) {
            auto oldest = weights_.find(window_.front());
            if (--oldest->second <= 0)
                weights_.erase(oldest);
            window_.pop_front();
        }
        return;
    }
    // Decay every weight once per arrival: O(tasks), and a design problem has few tasks.
    for (auto it = weights_.begin(); it != weights_.end();) {
        it->second *= lambda_;
        it = it->second < NEGLIGIBLE_WEIGHT ? weights_.erase(it) : std::next(it);
    }
    weights_[task] += 1;
}

Distribution DistributionEstimator::estimate() const { return normalized(weights_); }

double DistributionEstimator::effective_samples() const {
    if (config_.kind == EstimatorConfig::Kind::WINDOW)
        return static_cast<double>(window_.size());
    double total = 0;
    for (const auto &[task, w] : weights_)
        total += w;
    return total;
}

} // namespace envdesign::arrivals
