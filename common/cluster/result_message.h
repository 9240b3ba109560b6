#pragma once
// The result of a design search as the message ENVDESIGN_RESULT carries (design_result_t,
// SPEC.md's JSON): the coordinator publishes it, and the local CLI builds the same message,
// so that one formatter (clients/cpp, result_format.h) prints both.

#include "design/design_explanation.h"
#include "design/design_search.h"
#include "envdesign/design_result_t.hpp"

#include <string>

namespace envdesign::cluster {

// Counters only the coordinator knows, for design_result_t.counters.
struct TransportCounters {
    long long jobs_sent = 0;
    long long jobs_resent = 0;
    long long duplicates_ignored = 0;
    int planners_used = 0;
    double transport_seconds = 0;
    double job_seconds = 0;
    long long stored_answers = 0;
};

// design_result_t of a finished search (header fields left to the sender). With an
// `explanation` of result.best, it and the ranking's design points travel too.
envdesign::design_result_t result_message(const design::DesignProblem &problem,
                                          const design::DesignResult &result,
                                          const TransportCounters &transport,
                                          const design::DesignExplanation *explanation = nullptr);

// design_result_t of a request that failed: `exit_code` 2 (bad input) or 1.
envdesign::design_result_t error_result(int exit_code, const std::string &message);

} // namespace envdesign::cluster
