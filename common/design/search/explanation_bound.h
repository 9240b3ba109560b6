#pragma once
// The hitting-set phase's lower bound on the explaining robot's other option (robot_behaviour
// EXPLAINING, explaining.h), where every modification restricts or adds plans. In a design S
// whose modifications all restrict and edit only the human's model (a barrier seen only by
// people, a tape), the robot's model, and so its optimal plan pi_R (the planner's,
// deterministic), are the empty design's, and explaining task t costs at least
//     H * p_t * x * |E_t(S)|        (above the least IE and c_R*, which acting costs too).
// E_t(S) makes pi_R optimal in P_H(S) + E, and telling people a difference never makes an
// action cheaper, so every plan of P_H(S) cheaper than pi_R's human cost h_R must be broken by
// some difference of E. A pooled plan P (witness_bound.h) cheaper than h_R that S does not
// break is such a plan. Which differences of S can break it? Only one about a fact P relies
// on in P_H(S): an initial atom a step or the goal reads, a goal literal, a schema P uses.
// Either S holds a modification that touches P (witness.h; `Breakers::modifications`, which
// a design that keeps P may hold), or those facts are as in the empty design, in both models,
// and the difference is one of the empty design's, about a fact P reads there
// (`Breakers::differences`): a restricting human edit that does not touch P only removes init
// atoms P does not read positively or adds ones it does not read negatively. So |E_t(S)| is
// at least the least number of the empty design's differences that, with the touching
// modifications S holds, hit every such P: a second hitting set inside the phase's program
// (hitting_set.h). docs/design-search.md.
// Any other modification (`relaxing`) voids the argument in the designs that hold it: one
// that edits the robot's model (a lane, a physical barrier) may change pi_R and h_R (even a
// restricting one: the planner may then return another optimal plan), and one that adds
// plans to the human's model may add a difference that breaks P (an initial atom people
// are told of that the robot lacks) and makes pooled plans that need it. There the
// explaining option keeps only what every option pays (the constant and the robot's floor):
// each row above is relaxed by any such modification chosen, and pooled plans that need an
// addition get no row (they are plans only where it is chosen). Where none is chosen the
// argument holds as it stands.

#include "design/design_problem.h"
#include "design/evaluation/plan_cache.h"
#include "design/evaluation/task_evaluation.h"
#include "design/reconciliation/model_differences.h"
#include "design/search/deadline.h"
#include "design/search/witness_bound.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::design::witness {

class ExplanationBound {
public:
    // From the empty design's records (null where unknown); `problem` must outlive it.
    // Throws pddl::ParseError if a task's models do not build.
    ExplanationBound(const DesignProblem &problem, const TouchIndex &index,
                     const std::vector<Record> &root);

    // h_R: the human cost of the robot's optimal plan, where that plan is one of the human's
    // model with no modification; nullopt: no bound on explaining task t.
    std::optional<double> robot_plan_cost(int t) const { return tasks_[t].robot_plan_cost; }
    int differences(int t) const { return static_cast<int>(tasks_[t].differences.size()); }
    struct Breakers {
        std::vector<int> modifications; // every restricting one that touches the plan
        std::vector<int> differences;   // of task t with no modification (indices)
    };
    // The modifications that edit the robot's model or add plans: the bound does not hold
    // in a design that holds one.
    const std::vector<int> &relaxing() const { return relaxing_; }
    // What can break `plan`, a plan of task t's human model, in a design that keeps it.
    const Breakers &breaking(int t, const PooledPlan &plan) const;

    // Plans of task t's human model under `design` (restricting differences only remove plans,
    // so a plan of P_H(design) + E is one of P_H(design)), with their cost there, that the
    // minimal explanation of `x` meets and that no earlier call returned. The evaluator's
    // explanation search meets them too but keeps them to itself; pooled, each bounds the
    // explaining option of every design that keeps it, as any pooled plan does.
    std::vector<std::pair<std::vector<std::string>, double>>
    explanation_plans(const DesignProblem &problem, const Configuration &design, int t,
                      const TaskExplanation &x, const Deadline &deadline);
    // The searches explanation_plans ran (the evaluator's counters do not hold them).
    CacheCounters planner_counters() const { return planner_.counters(); }

private:
    struct Task {
        ModelPair models; // with no modification
        std::vector<ModelDifference> differences;
        std::optional<double> robot_plan_cost;
        mutable std::map<const void *, Breakers> breaking; // by the plan's steps
        std::set<std::vector<std::string>> returned;       // by explanation_plans
    };
    PlanCache planner_{planning::PlannerOptions{}}; // explanation_plans' own searches
    const TouchIndex &index_;
    Configuration every_; // every modification
    std::vector<int> relaxing_;
    std::vector<Task> tasks_;
};

} // namespace envdesign::design::witness
