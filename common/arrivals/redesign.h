#pragma once
// Re-evaluating a design problem for a new task distribution D, reusing every evaluation
// made before (stored_evaluator.h), and saying what changed and why.
//
// A Redesigner owns one design problem, an in-process LocalEvaluator (its content-addressed
// PlanCache kept across searches) and a StoredEvaluator with its EvaluationStore in front of
// it. Each redesign(D)
// sets the tasks' probabilities to D and runs the exact design search again: configurations
// whose tasks are all stored cost nothing; only configurations never evaluated (skipped or
// abandoned by the bounds under the old D, or cut short by a time limit) and new tasks go
// to the planners, and even those mostly hit the plan cache.
//
// New tasks (an arrival brought a task's PDDL problem) are parsed against the problem's
// domains and added before the search; one that fails to parse, or whose models do not
// ground during the search, is taken out again and reported as refused.
//
// Example:
//   Redesigner r(spec::load_design_problem("spec.textproto"), {});
//   Redesign first = r.redesign(r.distribution(), {});        // the spec's D
//   Redesign next = r.redesign({{"serve-g1", 0.1}, {"serve-g2", 0.9}}, {});
//   next.change.changed, next.change.explanation, next.change.planner_runs (0: re-weighting)
//   auto cheap = r.reweigh({{"serve-g1", 0.2}, {"serve-g2", 0.8}});  // store only, no planner
//   if (!cheap) ... planning is needed: wait for the drift threshold, then redesign()
//
// Not thread-safe; the problem must not be changed by anything else.

#include "arrivals/distribution.h"
#include "arrivals/tracker.h"
#include "design/design_run.h"
#include "design/evaluation/local_evaluator.h"
#include "design/evaluation/stored_evaluator.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::arrivals {

struct RedesignOptions {
    int workers = 1;                  // planner threads
    planning::PlannerOptions planner; // heuristic, limits
    int max_design_size = -1;         // < 0: the spec's
    double time_limit_s = -1;         // per redesign; < 0: the spec's; 0: none
    // Where evaluations are kept across restarts (store/state_dir.h); null: memory only.
    std::shared_ptr<store::RecordDb> evaluations;
};

struct DesignChange {
    bool changed = false;         // the design differs from the previous one
    design::Configuration before; // the previous design (empty on the first run)
    design::Configuration after;
    std::vector<std::string> before_names, after_names;
    Distribution d_before, d_after; // the probabilities before and after
    double distance = 0;            // TV(d_before, d_after)
    // The previous design's objective under the new D (NaN on the first run or when its
    // new tasks were never evaluated under it), beside the new design's.
    double objective_before;
    double objective_after;
    std::vector<std::string> added_tasks, refused_tasks;
    long long planner_runs = 0;   // in this redesign
    long long stored_answers = 0; // configurations answered from the store
    long long evaluated = 0;      // configurations evaluated (stored or not)
    double seconds = 0;
    std::string explanation; // one line: what changed and why
};

// A new task read against `problem`'s domains and checked as a spec load checks its tasks
// (both models parse, the pair compiles and grounds, every modification compiles on it).
// Throws pddl::ParseError, the text's position named "new-task:NAME:LINE:COL".
design::DesignTask parse_new_task(const design::DesignProblem &problem, const NewTask &task);

// A design run (result, explanation, warnings; the result's counters are this redesign's own)
// and what changed.
struct Redesign : design::DesignRun {
    DesignChange change;
};

class Redesigner {
public:
    Redesigner(design::DesignProblem problem, RedesignOptions options);

    const design::DesignProblem &problem() const { return *problem_; }
    Distribution distribution() const; // the tasks' probabilities now

    // Adds `new_tasks`, sets the probabilities to `d` (tasks `d` leaves out: 0; names the
    // problem does not have are ignored; if `d` gives every task 0, the current
    // probabilities stay) and searches. Throws only what the search throws besides bad
    // models of new tasks (e.g. a ParseError from a modification of the original tasks).
    Redesign redesign(const Distribution &d, const std::vector<NewTask> &new_tasks);

    // The same search for `d` (no new tasks) answered from the store alone: a planner is
    // never run. Returns the redesign when the search proved its design optimal for `d` (the
    // probabilities are `d` from then on); nullopt when it needed an evaluation the store
    // lacks, and then nothing changed. Microseconds to milliseconds: cheap enough to run on
    // every change of the estimate, so the design in force never lags a D the store covers.
    std::optional<Redesign> reweigh(const Distribution &d);
    long long reweighs() const { return reweighs_; }
    long long reweighs_needing_planning() const { return reweighs_needing_planning_; }

    const std::optional<design::EvaluatedDesign> &current() const { return current_; }
    const design::EvaluationStore &store() const { return store_; }

private:
    // Parses and appends a new task; the refusal message if it cannot.
    std::optional<std::string> add_task(const NewTask &task);
    void remove_task(const std::string &name);
    void set_probabilities(const Distribution &d);
    // One design run through `evaluator`; `planner` (null: none) plans the explanation.
    design::DesignRun search(design::Evaluator &evaluator, design::PlanCache *planner);
    double objective_of(const design::Configuration &configuration) const;
    DesignChange describe(const Redesign &redesign, const Distribution &d_before,
                          const std::vector<std::string> &added,
                          const std::vector<std::string> &refused) const;

    std::unique_ptr<design::DesignProblem> problem_; // stable address: the evaluators hold it
    RedesignOptions options_;
    std::unique_ptr<design::LocalEvaluator> local_;
    design::EvaluationStore store_;
    std::unique_ptr<design::StoredEvaluator> stored_;
    // reweigh(): the same store in front of an evaluator that refuses to plan.
    std::unique_ptr<design::Evaluator> no_planner_;
    std::unique_ptr<design::StoredEvaluator> store_only_;
    long long reweighs_ = 0;
    long long reweighs_needing_planning_ = 0;
    std::optional<design::EvaluatedDesign> current_;
};

} // namespace envdesign::arrivals
