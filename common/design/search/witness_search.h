#pragma once
// The exact design search that grows designs only where they can matter (`--search
// witness`, the default).
//
// Why it is exact. A configuration's objective depends only on optimal costs: per task, the
// optimum of P_mod (human cost, then robot cost) and the optimum of P_H. Call the optimal
// plans found for a configuration xi its witnesses. Let S be a set of restricting
// modifications (witness.h) none of which touches a witness of task t in xi. Each of them
// only removes plans, so the plans of xi + S are plans of xi, no cheaper; and the witnesses
// are still valid, at the same cost, since nothing they depend on changed. So they are still
// optimal, and task t's IE and robot cost in xi + S equal those in xi (*). If that holds for
// every task, objective(xi + S) = objective(xi) + beta * C(S) >= objective(xi), and xi, with
// fewer modifications, ranks before xi + S.
// Now let S* be the optimal design (SPEC.md's order) and xi a subset of it, starting from {}.
// If every modification of S* \ xi were restricting, of non-negative weighted cost and
// touched no witness of xi, xi would rank before S*: impossible. So some modification of
// S* \ xi touches a witness of xi, is not restricting, or has a negative cost; adding it
// gives a larger subset of S*. Hence S* is reached from {} by adding, one at a time, such a
// modification, and a search that adds exactly those (and all those) to every configuration
// it evaluates finds S*. Modifications that are not restricting or cost less than nothing
// are therefore added everywhere (the result's notes say which forced that).
//
// Bounds, valid for a configuration and all its supersets, so that a configuration whose
// bound cannot win is never evaluated and never grown (witness_bound.h):
//   - a task that no modification outside xi can touch keeps its value (*);
//   - any other task: IE at its least, robot cost at least c_R* of xi when every
//     modification outside xi is restricting for the robot (c_R* never drops), else 0;
//   - when everything outside is restricting: c_H(pi) never drops, and the human's optimum
//     is at most the cost of any known human plan still valid; pushing it above the k-th
//     cheapest one means breaking the cheaper ones, and each modification's cost is split
//     among the tasks whose plans it breaks. Otherwise, a task that keeps its value unless a
//     touching modification is added pays a share of the cheapest one.
// Before the search proper, probe designs that break each task's known cheaper plans teach
// it the plans these bounds need. Configurations are evaluated best first (least bound), so
// the search stops once the least open bound cannot beat the best design; a time limit
// leaves the proven gap.
// A configuration inherits a task's evaluation from the configuration it grew from when the
// added modification is restricting and touches none of that task's witnesses (*), or only
// the human's one while a known plan as cheap is still valid: the evaluator is asked only
// for the other tasks, and the visit costs a touch test. docs/design-search.md has more.

#include "design/search/design_result.h"

#include <optional>

namespace envdesign::design {

DesignResult search_witness(const DesignProblem &problem, Evaluator &evaluator,
                            const DesignSearchOptions &options,
                            const std::function<void(const SearchProgress &)> &progress);

// robot_behaviour EXPLAINING, where explaining_applies (witness_learning.h): the witness lemma
// does not hold (an explanation depends on every model difference), so no design is grown by
// its witnesses; the empty design, the probes and the hitting-set phase, with its bound on
// the explaining option (explanation_bound.h) and no cones, prove the answer alone. The
// result when that proves it or the deadline passes (best_found, the phase's gap); nullopt
// otherwise, and the caller searches exhaustively.
std::optional<DesignResult>
search_explaining_by_hitting_sets(const DesignProblem &problem, Evaluator &evaluator,
                                  const DesignSearchOptions &options,
                                  const std::function<void(const SearchProgress &)> &progress);

// robot_behaviour EXPLAINING where the phase does not prove the answer: the best-first queue
// with every modification weighed with every design (no witness lemma, so no task is kept from
// a subset), each design bounded by its robot bounds (carried up robot-restricting
// modifications, rising_bounds.h), IE floors and explanation floors. Exact like the exhaustive
// search, whose bounds these are, but the least bound first: a good design is met early and
// the robot's A* is skipped where a subset's bound stands in.
DesignResult search_every_design(const DesignProblem &problem, Evaluator &evaluator,
                                 const DesignSearchOptions &options,
                                 const std::function<void(const SearchProgress &)> &progress);

} // namespace envdesign::design
