#pragma once
// An Evaluator that keeps every task evaluation it has seen, so that a new task distribution
// D is a re-weighting and not a re-planning.
//
// A task's evaluation under a configuration (its most explicable plan, IE, robot cost) does
// not depend on D: D only weighs the tasks in the objective (objective.h). So the store is
// keyed by (configuration, task name) and outlives searches: when the design search for a
// new D asks for a configuration whose tasks are all stored, it is answered at once, with no
// job, no grounding and no planner. Only what was never evaluated goes to the inner
// evaluator: configurations the bounds skipped or abandoned under the old D, tasks added
// since, and work a time limit cut short (LIMIT answers are not stored).
//
// The DesignProblem must be the one the search and the inner evaluator use; tasks may be
// added to it between searches (their names are the keys, so indices may grow). Not
// thread-safe: evaluate() is called by one search at a time, as Evaluator requires.

#include "design/design_problem.h"
#include "design/evaluator.h"

#include <map>
#include <string>
#include <utility>

namespace envdesign::arrivals {

class StoredEvaluator : public design::Evaluator {
public:
    // Both must outlive the evaluator.
    StoredEvaluator(const design::DesignProblem &problem, design::Evaluator &inner);

    void evaluate(const std::vector<design::Configuration> &batch, const design::Deadline &deadline,
                  const design::EvaluationCallbacks &callbacks) override;
    // The inner evaluator's counters; configurations answered from the store add nothing.
    design::EvaluatorCounters counters() const override { return inner_.counters(); }

    // The stored evaluation of task `task` (a name) under `configuration`, or null.
    const design::TaskExplicability *find(const design::Configuration &configuration,
                                          const std::string &task) const;
    // Forgets every evaluation of task `task` (a task taken out of the problem again).
    void forget_task(const std::string &task);

    long long stored_answers() const { return stored_answers_; } // configurations, ever
    std::size_t size() const { return store_.size(); }

private:
    // Every task of `configuration` from the store, or nullopt if one is missing.
    std::optional<design::ConfigurationEvaluation>
    from_store(const design::Configuration &configuration) const;
    void keep(const design::ConfigurationEvaluation &evaluation);

    const design::DesignProblem &problem_;
    design::Evaluator &inner_;
    std::map<std::pair<design::Configuration, std::string>, design::TaskExplicability> store_;
    long long stored_answers_ = 0;
};

} // namespace envdesign::arrivals
