#pragma once
// Modifications that gate objects: the PDDL way to restrict an action for some objects
// without conditional effects. Such a modification makes init atoms of a *gate* G true;
// every schema that reads G is either a base schema T that needs G false or its twin T'
// that needs G true, at least T's other preconditions, and has T's effects and cost. It may
// also edit fluents F that only twins read (what T' waits for). Blocksworld's from-table-x
// marks (restricted x), so x is stacked only by stack-from-table, which needs (from-table x),
// set by pick-up and cleared by unstack.
//
// gated_twin_restricting says such a modification never lowers one model's optimal cost,
// combined with any other modifications. It checks, in that model:
//   - G is static (no schema or modification changes it, no task's init holds it) and read
//     by no goal and no added precondition or goal; every schema reading G reads it once,
//     and each that reads it positively is the twin of one that reads it negatively;
//   - no modification edits T or T';
//   - the F are read only by twins of the modification's gates, by no goal and no added
//     precondition or goal, and every modification that adds atoms of these gates or
//     mentions an F edits the F exactly as this one does.
// Then a plan of M + {this} becomes a plan of M at the same cost, for any set M: each step
// of T' on a gate atom that M lacks becomes the step of T (its other preconditions hold,
// the atom is false in M, effects and cost are the same). If M gates with these predicates
// too, the F change the same way in both models; if not, M holds no gate atom, every twin
// step is replaced, and nothing left reads an F (docs/design-search.md).

#include "design/design_problem.h"

namespace envdesign::design {

// Whether `modification`'s edits of the robot's (`robot`) or the human's model only gate, as
// above; false when unsure.
bool gated_twin_restricting(const DesignProblem &problem, int modification, bool robot);

} // namespace envdesign::design
