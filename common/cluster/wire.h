#pragma once
// Between the design engine's structs and the LCM messages of the planner channels:
// jobs (dispatcher.h's Job plus its configuration), their answers (TaskExplicability or a
// robot-cost bound) and the result of a search (design_result_t, SPEC.md's JSON).

#include "design/design_search.h"
#include "design/dispatcher.h"
#include "envdesign/design_result_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "heuristics/heuristic.h"

#include <optional>
#include <string>

namespace envdesign::cluster {

// design_request_t::HEURISTIC_* -> the planner's heuristic (unknown values: LM-cut).
heuristics::HeuristicKind heuristic_kind(std::int8_t heuristic);

// The job_t of `job` (job_id, planner, attempt, utime are the sender's to fill).
envdesign::job_t job_message(const design::Job &job, const design::Configuration &configuration,
                             std::int64_t request_id, const std::string &spec_hash,
                             std::int8_t heuristic, const design::Deadline &deadline);

// Why `job` does not fit `problem` (kind, task or modification indices out of range,
// configuration not ascending, heuristic or time limit invalid); nullopt when it fits.
std::optional<std::string> job_problem(const envdesign::job_t &job,
                                       const design::DesignProblem &problem);

design::Configuration configuration_of(const envdesign::job_t &job);

// Why an answer cannot be taken (unknown status, kind mismatch, an ill-formed value).
std::optional<std::string> evaluation_problem(const envdesign::evaluation_t &evaluation,
                                              std::int8_t kind);

// Fills the answer fields of `evaluation` (status, values, plan).
void put_explicability(const design::TaskExplicability &task, envdesign::evaluation_t &evaluation);
void put_robot_bound(std::optional<double> bound, envdesign::evaluation_t &evaluation);

// The dispatcher's view of an answer that passed evaluation_problem.
design::JobAnswer job_answer(const design::Job &job, const envdesign::evaluation_t &evaluation);

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

// design_result_t of a finished search (header fields left to the sender).
envdesign::design_result_t result_message(const design::DesignProblem &problem,
                                          const design::DesignResult &result,
                                          const TransportCounters &transport);

// design_result_t of a request that failed: `exit_code` 2 (bad input) or 1.
envdesign::design_result_t error_result(int exit_code, const std::string &message);

} // namespace envdesign::cluster
