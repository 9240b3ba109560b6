#pragma once
// When to ask for a re-evaluation: the total variation distance between the D of the design
// in force (the reference) and the estimate, with hysteresis so that noise never makes the
// detector flap.
//
//   ARMED    --TV >= threshold, enough evidence, hold-off passed-->  PENDING (request sent)
//   PENDING  --answered(D'), D' is the D requested-->                ARMED
//   PENDING  --answered(D'), TV(D', estimate) <  rearm_threshold-->  ARMED
//   PENDING  --answered(D'), otherwise-->                            HELD
//   PENDING  --no answer for answer_timeout_s-->                     ARMED (a timeout; seen
//                                    at an arrival or on the clock; no hold-off after it)
//   HELD     --TV < rearm_threshold-->                               ARMED
//   HELD     --TV >= threshold and retry_s since the request-->      PENDING (a retry)
//
// Three things keep it from flapping: at most one request is in flight; the answer moves the
// reference to the D the design was made for, so the next request needs the estimate to move
// `threshold` away from there (a band of width `threshold` around every evaluated D, the
// hysteresis that keeps a D near a design boundary from flipping the design back and forth);
// and a request needs `holdoff_arrivals` fresh arrivals since the previous one. An answer
// for the D requested (within rearm_threshold) re-arms at once, even if the estimate moved on
// meanwhile: that is drift going on, and the next request follows it. HELD covers an answer
// for another D that leaves the estimate far from the design's (the coordinator evaluated
// something else, or refused): asking again at every arrival would flap, so it asks only
// after `retry_s`, or re-arms once the estimate comes back within rearm_threshold.
//
// Example (two tasks, threshold 0.2):
//   DriftDetector d(config, {{"a", 0.9}, {"b", 0.1}});
//   d.observe({{"a", 0.6}, {"b", 0.4}}, 200, now);  // TV 0.3: true, now PENDING
//   d.answered({{"a", 0.6}, {"b", 0.4}}, estimate, now);  // ARMED again, reference moved

#include "arrivals/distribution.h"

namespace envdesign::arrivals {

struct DriftConfig {
    double threshold = 0.2;        // request when TV(reference, estimate) >= this
    double rearm_threshold = 0.1;  // < threshold: re-armed when TV falls below this
    double min_samples = 50;       // no request on less evidence (effective samples)
    int holdoff_arrivals = 20;     // arrivals between two requests
    double answer_timeout_s = 120; // PENDING without an answer this long: a timeout
    double retry_s = 30;           // HELD: ask again this long after the last request
};

enum class DriftState { ARMED, PENDING, HELD };

class DriftDetector {
public:
    DriftDetector(DriftConfig config, Distribution reference);

    // Called after every accepted arrival with the new estimate, its effective sample size
    // and the time (seconds on a monotonic clock). True: send a re-evaluation request now.
    bool observe(const Distribution &estimate, double samples, double now);
    // The same check on the clock, with no new arrival: a request or its answer lost after
    // the last arrival must still time out (PENDING -> ARMED) and a HELD retry fall due.
    bool recheck(const Distribution &estimate, double samples, double now);

    // A request for `requested` whatever the distance (a new task must be evaluated, or the
    // first design made): true unless one is already PENDING.
    bool force(double now, const Distribution &requested);

    // The D of the design now in force (the coordinator's answer, or any new result for the
    // problem), with the estimate at that moment.
    void answered(const Distribution &reference, const Distribution &estimate);

    // A re-weighting (tracker.h) proved the design in force optimal for `reference`: measure
    // from there. No request was answered, so the state stays (HELD re-arms if close):
    // the estimate moving on while the re-weighting ran is drift to follow, not a refusal.
    void rebase(const Distribution &reference, const Distribution &estimate);

    DriftState state() const { return state_; }
    const Distribution &reference() const { return reference_; }
    double last_distance() const { return last_tv_; }
    long long requests() const { return requests_; }
    long long timeouts() const { return timeouts_; }

private:
    bool request(double now, const Distribution &requested);

    DriftConfig config_;
    Distribution reference_;
    Distribution requested_; // the D of the last request
    DriftState state_ = DriftState::ARMED;
    double last_tv_ = 0;
    double requested_at_ = 0;
    long long arrivals_since_request_ = 0;
    bool requested_before_ = false;
    long long requests_ = 0;
    long long timeouts_ = 0;
};

const char *to_string(DriftState state);

} // namespace envdesign::arrivals
