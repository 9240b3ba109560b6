#pragma once
// The first stop of every arrival: checks it, numbers it, and counts what is wrong with it.
// Bad samples are never fatal; they are counted by kind (and logged by the caller through a
// LogThrottle, so that a flood of them cannot flood the log either).
//
// Checks, in order (the first failing one is the verdict):
//   UNKNOWN_PROBLEM  problem_id names no design problem the bridge tracks
//   EMPTY_TASK       no task name
//   BAD_NAME         a name longer than max_name_length or with control characters
//   TOO_LARGE        a new task's problem text beyond max_problem_bytes
//   BAD_TIMESTAMP    utime <= 0, or more than max_age_s behind or ahead of the bridge's clock
//   BAD_SEQUENCE     sequence_number <= 0
//   DUPLICATE        a sequence number of this (problem, site) already seen (a sample
//                    delivered twice, or a replay); sequence 1 after a higher one is taken
//                    as the site restarting instead
//   TOO_MANY_SITES   a new (problem, site) beyond max_sites (bounds the bridge's memory)
//   RATE_LIMITED     beyond max_rate arrivals per second from this (problem, site), with a
//                    burst of `burst` (a token bucket on the bridge's monotonic clock)
// An arrival stamped more than max_future_s ahead of the bridge's clock is accepted and
// counted in `clock_skewed`: the publisher's clock (or the bridge's) is off. The estimate
// uses arrival order, never timestamps, so a skewed site still moves it; rejecting its
// arrivals would silently freeze the estimate of a site whose clock runs 5 minutes fast.
// Sequence numbers are followed for every sample of a known problem with a usable site,
// whatever else is wrong with it (it did arrive). Arrivals whose sequence skips numbers add
// the skipped count to `sequence_gaps`
// (samples lost on the way, or overwritten in the reader's history during a flood); the
// first arrival seen from a site adds the numbers before it to `sequence_unseen` (a bridge
// that starts late cannot tell those sent before it from those lost).
//
// Not thread-safe; the bridge calls it from the thread that takes the DDS samples.

#include "arrivals/arrival.h"

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::arrivals {

struct IntakeConfig {
    double max_future_s = 300;          // beyond this ahead of the bridge: clock_skewed
    double max_age_s = 7 * 24 * 3600.0; // oldest arrival accepted (and furthest ahead)
    double max_rate = 0;                // per (problem, site), arrivals/s; 0: no limit
    double burst = 1000;                // token bucket size for max_rate
    std::size_t max_name_length = 256;  // problem_id, site, task
    std::size_t max_problem_bytes = 1 << 20;
    std::size_t max_sites = 10000; // (problem, site) pairs remembered
};

enum class Verdict {
    ACCEPTED,
    UNKNOWN_PROBLEM,
    EMPTY_TASK,
    BAD_NAME,
    TOO_LARGE,
    BAD_TIMESTAMP,
    BAD_SEQUENCE,
    DUPLICATE,
    TOO_MANY_SITES,
    RATE_LIMITED,
};
inline constexpr int VERDICTS = static_cast<int>(Verdict::RATE_LIMITED) + 1;

// "unknown_problem", "empty_task", ... (also the names of the counters on the bus).
const char *to_string(Verdict verdict);

struct IntakeCounters {
    long long received = 0;
    long long by_verdict[VERDICTS] = {}; // indexed by Verdict; [ACCEPTED] counts accepted
    long long sequence_gaps = 0;         // sequence numbers skipped by accepted arrivals
    long long sequence_unseen = 0;       // numbers before the first arrival seen from a site:
                                         // sent before the bridge started, or lost
    long long site_restarts = 0;         // sequence 1 again after a higher one
    long long clock_skewed = 0;          // accepted with utime beyond max_future_s ahead
    double last_skew_s = 0;              // how far ahead the last of them was, seconds

    long long count(Verdict v) const { return by_verdict[static_cast<int>(v)]; }
    long long rejected() const { return received - count(Verdict::ACCEPTED); }
};

class ArrivalIntake {
public:
    explicit ArrivalIntake(IntakeConfig config) : config_(config) {}

    // `problem_known`: whether the arrival's problem_id is tracked; `now` seconds on a
    // monotonic clock (for the rate limit); `now_utime` the wall clock in microseconds
    // since the Unix epoch (for the timestamp check).
    Verdict check(const Arrival &arrival, bool problem_known, double now, int64_t now_utime);
    // Whether the last check() accepted an arrival stamped beyond max_future_s ahead.
    bool last_skewed() const { return last_skewed_; }

    const IntakeCounters &counters() const { return counters_; }

private:
    struct Site {
        int64_t last_sequence = 0;
        double tokens = 0;
        double refilled_at = 0;
    };

    Verdict check_fields(const Arrival &arrival, bool problem_known, int64_t now_utime) const;
    Verdict check_sequence(Site &site, int64_t sequence);
    bool take_token(Site &site, double now);

    IntakeConfig config_;
    IntakeCounters counters_;
    bool last_skewed_ = false;
    std::map<std::pair<std::string, std::string>, Site> sites_;
};

// Which bad samples to log: the first `first` of each kind, then at most one line per
// `interval_s` per kind saying how many were not logged in between.
class LogThrottle {
public:
    LogThrottle(int first = 5, double interval_s = 10) : first_(first), interval_s_(interval_s) {}

    struct Decision {
        bool log = false;
        long long suppressed = 0; // samples of this kind not logged since the last line
    };
    Decision should_log(Verdict verdict, double now);
    // Kinds with samples not logged for `interval_s`, and how many: for a summary line once a
    // flood has stopped (nothing else would say how much was left out). Resets their counts.
    std::vector<std::pair<Verdict, long long>> overdue(double now);

private:
    struct Kind {
        long long seen = 0;
        long long suppressed = 0;
        double logged_at = 0;
    };
    int first_;
    double interval_s_;
    Kind kinds_[VERDICTS];
};

} // namespace envdesign::arrivals
