#pragma once
// The boundary between the design search (the coordinator) and the planners.
//
// The search hands batches of configurations to an Evaluator and gets back, for each, the
// explicability of every task. A configuration may come with some tasks (and robot-cost
// bounds) already known: the witness search inherits them from a smaller configuration
// (witness_search.h); the evaluator works only on the rest and passes the known ones through. How
// the work is done is the evaluator's business: the in-process LocalEvaluator (local_evaluator.h)
// runs N planner threads over a shared content-addressed plan cache; an evaluator speaking to
// planner services over LCM (issue 5) implements the same interface, and the search does not
// change.
//
// The search keeps control of what is worth evaluating: before each task of a configuration
// is started and after each one finishes, the evaluator asks `abandon` whether the
// configuration can still win; if not, it drops the rest (status CUT_OFF). An evaluator may
// first find cheap lower bounds (robot_cost_bounds, ie_floors) to sharpen that question. Both
// callbacks run on the thread that called evaluate(), never concurrently.

#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/search/deadline.h"

#include <functional>
#include <optional>
#include <vector>

namespace envdesign::design {

enum class EvaluationStatus {
    COMPLETE, // every task evaluated
    CUT_OFF,  // abandoned: proven not to win
    LIMIT,    // the deadline passed before every task was evaluated
};

struct ConfigurationEvaluation {
    Configuration configuration;
    EvaluationStatus status = EvaluationStatus::LIMIT;
    std::vector<std::optional<TaskExplicability>>
        tasks; // per task of the spec; unset: not evaluated
    // Per task, a lower bound on c_R(pi) known before the task is evaluated: the optimal
    // cost of the robot's own model (the most explicable plan is one of its plans).
    std::vector<std::optional<double>> robot_cost_bounds;
    // Per task, a lower bound on its IE known before the task is evaluated (ie_floor in
    // explicability.h), where the evaluator could argue one; unset: the least IE.
    std::vector<std::optional<double>> ie_floors;
    // Per task, for a robot that may explain: a lower bound on the size of any explanation,
    // known before the task is evaluated (explanation_floor.h); unset: one where the IE floor
    // is above the least IE, else none.
    std::vector<std::optional<int>> explanation_floors = {};
};

// A configuration with nothing known yet.
ConfigurationEvaluation unevaluated(Configuration configuration);

struct EvaluationCallbacks {
    std::function<bool(const ConfigurationEvaluation &partial)> abandon;
    std::function<void(ConfigurationEvaluation evaluation)> done;
};

struct EvaluatorCounters {
    long long task_evaluations = 0; // (configuration, task) pairs evaluated
    long long planner_runs = 0;
    long long cache_hits = 0;
    long long groundings_skipped = 0; // cache hits found before grounding
    double planner_seconds = 0;
};

class Evaluator {
public:
    virtual ~Evaluator();
    // Evaluates every configuration of `batch` (or abandons it, or runs out of time) and
    // calls callbacks.done once for each, in completion order, before returning.
    // In `batch`, `tasks` and `robot_cost_bounds` hold what is known (either may be empty:
    // nothing is); `status` is ignored.
    virtual void evaluate(const std::vector<ConfigurationEvaluation> &batch,
                          const Deadline &deadline, const EvaluationCallbacks &callbacks) = 0;
    virtual EvaluatorCounters counters() const = 0;
    // Configurations it can answer in full without a planner (an evaluator over stored
    // evaluations: a new task distribution is a re-weighting); the witness search learns
    // from them first. At most `limit` of them.
    virtual std::vector<Configuration> known_configurations(std::size_t /*limit*/) { return {}; }
};

} // namespace envdesign::design
