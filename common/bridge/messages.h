#pragma once
// The bridge's LCM messages: task_distribution_t from the tracker's state, and the D a
// design_result_t was made for.

#include "arrivals/tracker.h"
#include "bus/channels.h"
#include "envdesign/design_result_t.hpp"
#include "envdesign/task_distribution_t.hpp"

#include <string>
#include <vector>

namespace envdesign::bridge {

// The design in force for a problem, as the bridge last heard it.
struct DesignInForce {
    std::vector<std::string> design; // modification names
    double objective;                // NaN: not known yet
    std::string last_change;         // what changed and why, one line
    std::int64_t request_id = 0;     // the last re-evaluation asked for
};

// Header fields (utime, request_id, sender) are the caller's.
envdesign::task_distribution_t distribution_message(const arrivals::ProblemStatus &status,
                                                    const arrivals::IntakeCounters &counters,
                                                    const arrivals::TrackerConfig &config,
                                                    const DesignInForce &design);

// The same with the request's D, reason and new tasks.
envdesign::task_distribution_t request_message(const arrivals::Request &request,
                                               const arrivals::ProblemStatus &status,
                                               const arrivals::IntakeCounters &counters,
                                               const arrivals::TrackerConfig &config,
                                               const DesignInForce &design);

// The tasks' probabilities of a result (its D); empty when it has no design.
arrivals::Distribution distribution_of(const envdesign::design_result_t &result);

} // namespace envdesign::bridge
