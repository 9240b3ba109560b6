#pragma once
// What a plan of the human's model reads, so that explanation searches ask the validator only
// about differences that can change the plan (explanation_hitting.h, explanation_floor.h).
//
// A plan's validity and cost depend on the schemas of its steps, the ground atoms their
// preconditions and the goal read, and nothing else: effects are unconditional, so an initial
// atom no step or goal reads changes no step. A difference about none of these leaves the plan
// as it is, alone or with any others.

#include "design/model/configuration.h"
#include "design/reconciliation/model_differences.h"

#include <set>
#include <string>
#include <vector>

namespace envdesign::design {

// `known` false: a step did not match a schema of the human's model; every difference counts.
// `from_init`: the atoms a step's positive precondition or the positive goal reads before any
// step adds them (a step reads before its own effects).
struct PlanReads {
    bool known = false;
    std::set<std::string> schemas;
    std::set<pddl::Atom> atoms;
    std::set<pddl::Atom> from_init;
};

PlanReads plan_reads(const ModelPair &models, const std::vector<std::string> &plan);

// Whether `d` is about something the plan reads (always, when the reads are not known).
bool may_break(const ModelDifference &d, const PlanReads &reads);

} // namespace envdesign::design
