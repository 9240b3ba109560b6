#pragma once
// The bridge's two clocks, handed in so that tests set the time: a monotonic one for rate
// limits and hold-offs, and the wall clock that arrival timestamps are compared with.
//
//   ManualClock clock(1'700'000'000'000'000);  // wall clock at the start, microseconds
//   Bridge bridge(bus, config, queue, clock);
//   clock.advance(0.5);                          // both clocks move on by 0.5 s

#include <atomic>
#include <chrono>
#include <cstdint>

namespace envdesign::bridge {

class Clock {
public:
    virtual ~Clock() = default;
    virtual double seconds() const = 0;     // monotonic, any origin
    virtual std::int64_t utime() const = 0; // wall clock, microseconds since the Unix epoch
};

// steady_clock and system_clock; thread-safe.
class SystemClock : public Clock {
public:
    double seconds() const override;
    std::int64_t utime() const override;

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Time stands still until advance(); thread-safe.
class ManualClock : public Clock {
public:
    explicit ManualClock(std::int64_t utime) : utime_(utime) {}
    double seconds() const override { return static_cast<double>(elapsed_us_) * 1e-6; }
    std::int64_t utime() const override { return utime_ + elapsed_us_; }
    void advance(double seconds) { elapsed_us_ += static_cast<std::int64_t>(seconds * 1e6); }

private:
    std::int64_t utime_;
    std::atomic<std::int64_t> elapsed_us_{0};
};

} // namespace envdesign::bridge
