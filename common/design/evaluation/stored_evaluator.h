#pragma once
// An Evaluator in front of another that answers from an EvaluationStore
// (evaluation_store.h) whatever was evaluated before, so that a new task distribution D is
// a re-weighting and not a re-planning.
//
// When the design search for a new D asks for a configuration whose tasks are all stored,
// it is answered at once: no job, no grounding, no planner. A configuration known in part
// (it was abandoned before) is first shown to the search's `abandon` with what is stored,
// its robot-cost bounds included; if the search drops it, again no planner. Only the rest
// goes to the inner evaluator: configurations the bounds skipped or abandoned under the old
// D and now needed, tasks added since, work a time limit cut short. Its answers and bounds
// are stored on the way back (those of abandoned configurations too).
//
//   EvaluationStore store;                      // kept across searches of this problem
//   LocalEvaluator local(problem, workers);     // or the coordinator's LcmEvaluator
//   StoredEvaluator stored(problem, local, store);
//   search_design(problem, stored, options);    // again after changing the probabilities
//
// Tasks may be added to or taken out of the problem between evaluate() calls, not changed
// in place: a task's key is computed once and found again by its name. evaluate() runs on one
// thread at a time, as the Evaluator interface says.

#include "design/design_problem.h"
#include "design/evaluation/evaluation_store.h"
#include "design/evaluation/evaluator.h"

#include <string>
#include <utility>
#include <vector>

namespace envdesign::design {

class StoredEvaluator : public Evaluator {
public:
    // All three must outlive the evaluator; `store` must be the one for
    // store_key(problem).
    StoredEvaluator(const DesignProblem &problem, Evaluator &inner, EvaluationStore &store);

    void evaluate(const std::vector<ConfigurationEvaluation> &batch, const Deadline &deadline,
                  const EvaluationCallbacks &callbacks) override;
    // The inner evaluator's counters: configurations answered from the store add nothing.
    EvaluatorCounters counters() const override { return inner_.counters(); }
    // Configurations stored for every task of the problem.
    std::vector<Configuration> known_configurations(std::size_t limit) override;

    // The stored evaluation of task index `task` under `configuration`.
    std::optional<TaskExplicability> find(const Configuration &configuration, int task);
    // Configurations answered from the store (complete, or abandoned on stored knowledge).
    long long stored_answers() const { return stored_answers_; }

    // Stores one answer of the inner evaluator as it arrives, before its configuration is
    // done (an evaluator over a network calls these, so that a durable store holds every
    // answer even if the process dies mid-configuration). Same thread as evaluate().
    void keep_task(const Configuration &configuration, int task,
                   const TaskExplicability &evaluation);
    void keep_robot_bound(const Configuration &configuration, int task, const RobotBound &bound);

private:
    const TaskKey &key(int task);
    // What the store knows of `configuration` (status COMPLETE when every task is known).
    ConfigurationEvaluation from_store(const ConfigurationEvaluation &request);
    void keep(const ConfigurationEvaluation &evaluation, const ConfigurationEvaluation &request);

    const DesignProblem &problem_;
    Evaluator &inner_;
    EvaluationStore &store_;
    std::vector<std::pair<std::string, TaskKey>> task_keys_; // by task index: name, key
    long long stored_answers_ = 0;
};

} // namespace envdesign::design
