#pragma once
// The result of a design search as the message ENVDESIGN_RESULT carries (design_result_t,
// SPEC.md's JSON): the coordinator publishes it, and the local CLI builds the same message,
// so that one formatter (clients/cpp, result_format.h) prints both.

#include "design/design_run.h"
#include "envdesign/design_result_t.hpp"

#include <string>

namespace envdesign::wire {

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

// design_result_t of a finished run (header fields left to the sender): the result, its
// warnings and, when the run explained it, the explanation and the ranking's design points.
envdesign::design_result_t result_message(const design::DesignProblem &problem,
                                          const design::DesignRun &run,
                                          const TransportCounters &transport = {});

// At most this many warnings travel (the message counts them in an int16), each cut to
// MAX_WARNING_BYTES: a warning may quote a goal, and a result must stay far below the bus's
// largest message. A last line says how many more there were.
constexpr std::size_t MAX_WARNINGS = 1000;
constexpr std::size_t MAX_WARNING_BYTES = 1024;

// design_result_t of a request that failed: `exit_code` 2 (bad input) or 1.
envdesign::design_result_t error_result(int exit_code, const std::string &message);

} // namespace envdesign::wire
