#pragma once
// Minimal explanations by implicit hitting sets, exact when every difference is restricting
// for the human's model (minimal_explanation.h chooses this method then, else it enumerates
// subsets).
//
// A difference is restricting when applying it can only remove plans of P_H: removing an
// initial atom, adding a positive precondition or goal, adding a delete effect, removing an
// add effect or an action, where the predicate is never read negatively (no (not ...) in a
// precondition or goal of either model), and no predicate is both required anew (an added
// precondition or goal) and shrunk (an initial atom removed, a delete added, an add removed).
// Then for a fixed action sequence pi, validity is closed under union: pi valid in P_H + E1
// and in P_H + E2 implies pi valid in P_H + (E1 u E2). (Shrinks change only the atoms of
// their predicates, and along pi the states of P_H + (E1 u E2) contain the intersection of
// the other two, by induction over the steps; added requirements read predicates no
// difference shrinks, whose atoms evolve alike in all three; every read is positive.) Without
// the last condition it fails: Blocksworld's (handempty) precondition alone, or its delete
// alone, keeps a plan holding two blocks valid; both together do not. Hence:
//   - pi_R is valid in P_H + E iff pi_R is valid in P_H and no d in E alone breaks it: the
//     differences that break pi_R alone are never candidates;
//   - a plan pi' of P_H + E cheaper than pi_R is a plan of P_H + E* unless E* holds some d that
//     breaks pi' alone: every explanation hits T(pi') = {d : pi' invalid in P_H + {d}}.
// The search: E = a least hitting set of the sets T found so far (exact); plan P_H + E; if
// its optimum equals c(pi_R), E is minimal (every explanation hits every T, and E is a least
// such set); else T(pi'), of the plan found, is a new set E does not hit (pi' is valid in
// P_H + E), so the loop ends. T(pi') empty: no explanation exists.
// Any plan of P_H cheaper than pi_R gives such a T, wherever it was met: the search starts
// from the sets of the plans earlier searches met (other designs of the same task, whose
// human models differ: PlanCache::cheaper_plans), so one planner call often ends it.
// Ties: once some least hitting set E explains, the lexicographically least one L of the same
// sets is told as well (when it differs); if it explains, it is the answer, else its plan's T
// joins the sets and the loop goes on. L is then the lexicographically least minimal
// explanation: every explanation hits every T known, so none is smaller than E, and every
// minimal one is a least hitting set of the sets known, of which L is the least. So the answer
// does not depend on which plans were met before, nor on which least hitting sets the rounds before
// the last tried (finding the lexicographically least one costs up to an order of magnitude
// more than finding one, and the rounds on a floor's sight lines number hundreds).

#include "design/evaluation/plan_cache.h"
#include "design/reconciliation/explanation_search.h"
#include "design/search/deadline.h"

namespace envdesign::design {

// Whether every difference is restricting as above.
bool all_restricting(const ModelPair &models, const std::vector<ModelDifference> &differences);

// A least subset of `sets` (each a list of indices) hitting all of them, ascending; `size` the
// number of indices. Exact. Of equally small ones, the lexicographically least.
// `at_least`: a size no hitting set is below, if the caller knows one (the least hitting set
// of some of `sets` has it), else 0; it saves proving the smaller sizes empty.
std::vector<int> least_hitting_set(const std::vector<std::vector<int>> &sets, int size,
                                   int at_least = 0);

// A least subset of `sets` hitting all of them, ascending, not necessarily the
// lexicographically least: faster, for the rounds before the last.
std::vector<int> some_least_hitting_set(const std::vector<std::vector<int>> &sets, int size,
                                        int at_least = 0);

// minimal_explanation's search when all_restricting(models, search.differences) holds.
void hitting_set_explanation(const ModelPair &models, const std::vector<std::string> &robot_plan,
                             PlanCache &planner, const Deadline &deadline,
                             ExplanationSearch &search);

} // namespace envdesign::design
