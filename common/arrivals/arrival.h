#pragma once
// Overview: task arrivals and what envdesign-bridge makes of them (issue 6).
//
// Warehouse systems publish one TaskArrival (dds/task_arrival.idl) per task they start. The
// bridge turns the stream into an estimate of the task distribution D of each design problem
// and asks for a re-evaluation of the design when D has drifted far enough:
//
//   Arrival -> ArrivalIntake (intake.h: checks, counters, duplicates, floods)
//           -> ProblemTracker (tracker.h: known tasks, new tasks)
//                -> DistributionEstimator (estimator.h: sliding window or exponential decay)
//                -> DriftDetector (drift_detector.h: total variation vs the design's D, with
//                   hysteresis)
//           -> a re-evaluation request; the coordinator answers with a new design
//              (redesign.h re-weights stored evaluations instead of planning again).
//           -> on every change of the estimate (rate-limited, tracker.h reweighs_due): a
//              re-weighting over the stored evaluations alone (Redesigner::reweigh), so the
//              design in force follows D wherever no planner is needed.
//
// Everything in this folder is transport-free and takes the time as an argument, so that
// tests drive it with hand-made clocks; common/dds and services/bridge connect it to DDS
// and LCM.

#include <cstdint>
#include <string>

namespace envdesign::arrivals {

// One task arrival, as read from DDS (the C++ mirror of envdesign_dds_TaskArrival).
struct Arrival {
    std::string problem_id;    // the design problem
    std::string site;          // the reporting site; (problem_id, site) is the DDS instance
    std::string task;          // task name in the design problem
    int64_t sequence = 0;      // per (problem_id, site), from 1
    int64_t utime = 0;         // arrival time, microseconds since the Unix epoch
    std::string problem;       // PDDL problem text of a new task, or empty
    std::string human_problem; // the observers' problem of a new task; empty: `problem`
};

} // namespace envdesign::arrivals
