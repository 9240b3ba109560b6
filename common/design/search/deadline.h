#pragma once
// A point in time after which the design search stops (the spec's time_limit_s or
// --time-limit). Unlimited by default. It may also watch a stop flag (Ctrl-C): once the flag
// is set the deadline has passed, so the search stops as at a time limit and returns the
// best design so far. A planner call already running sees the flag too (SearchLimits::stop).

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>

namespace envdesign::design {

class Deadline {
public:
    Deadline() = default;
    // `seconds` <= 0: no limit.
    static Deadline in(double seconds) {
        Deadline d;
        if (seconds > 0)
            d.at_ = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(seconds));
        return d;
    }

    // The same deadline, passed also once `*stop` is true; `stop` outlives every copy.
    Deadline with_stop(const std::atomic<bool> *stop) const {
        Deadline d = *this;
        d.stop_ = stop;
        return d;
    }

    bool limited() const { return at_.has_value(); }
    const std::atomic<bool> *stop_flag() const { return stop_; } // null: none
    bool expired() const {
        return (stop_ && stop_->load(std::memory_order_relaxed)) ||
               (at_ && std::chrono::steady_clock::now() >= *at_);
    }
    // Seconds left (at least a millisecond so a planner call gets a positive limit);
    // 0 means unlimited.
    double remaining_seconds() const {
        if (!at_)
            return 0;
        double left =
            std::chrono::duration<double>(*at_ - std::chrono::steady_clock::now()).count();
        return std::max(left, 0.001);
    }

private:
    std::optional<std::chrono::steady_clock::time_point> at_;
    const std::atomic<bool> *stop_ = nullptr;
};

} // namespace envdesign::design
