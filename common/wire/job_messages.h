#pragma once
// Between the design engine's structs and the LCM messages of the planner channels:
// jobs (dispatcher.h's Job plus its configuration), their answers (TaskExplicability or a
// robot-cost bound); the result of a search is result_message.h's.

#include "design/evaluation/dispatcher.h"
#include "design/search/design_search.h"
#include "envdesign/design_result_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "heuristics/heuristic.h"
#include "wire/result_message.h"

#include <optional>
#include <string>

namespace envdesign::wire {

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
// The job a planner runs for `job` (its kind and task; configuration 0).
design::Job job_of(const envdesign::job_t &job);

// Why an answer cannot be taken (unknown status, kind mismatch, an ill-formed value).
std::optional<std::string> evaluation_problem(const envdesign::evaluation_t &evaluation,
                                              std::int8_t kind);

// Fills the answer fields of `evaluation` (status, values, plan; or the bounds) from a
// planner's answer to the job (LocalEvaluator::answer).
void put_answer(const design::JobAnswer &answer, envdesign::evaluation_t &evaluation);

// The dispatcher's view of an answer that passed evaluation_problem.
design::JobAnswer job_answer(const design::Job &job, const envdesign::evaluation_t &evaluation);

} // namespace envdesign::wire
