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
// Bounds, valid for a configuration and all its supersets (so a configuration whose bound
// cannot win is never evaluated and never grown):
//   - a task that no modification outside xi can touch keeps its value (*);
//   - any other task: IE at its least, robot cost at least c_R* of xi when every
//     modification outside xi is restricting for the robot (c_R* never drops), else 0;
//   - a task that keeps its value unless one of its touching modifications T_t is added
//     costs, beyond that least value, min(its excess, min over m in T_t of
//     beta * c_m / deg(m)), deg(m) the number of tasks m touches: the cost of each added
//     modification is shared among the tasks it changes (non-negative costs only).
// Configurations are evaluated best first (least bound), so the search stops once the least
// open bound cannot beat the best design; a time limit leaves the proven gap.
// A configuration inherits a task's evaluation from the configuration it grew from when the
// added modification is restricting and touches none of that task's witnesses (*): the
// evaluator is asked only for the other tasks, and the visit costs a touch test.

#include "design/design_search.h"

namespace envdesign::design {

DesignResult search_witness(const DesignProblem &problem, Evaluator &evaluator,
                            const DesignSearchOptions &options,
                            const std::function<void(const SearchProgress &)> &progress);

} // namespace envdesign::design
