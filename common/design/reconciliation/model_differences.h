#pragma once
// The differences between the robot's model P_R and the human's model P_H of one task (model
// reconciliation, Chakraborti et al., IJCAI 2017), after the design's edits. Each is one fact
// that one model has and the other does not:
//   - an initial atom;
//   - a goal literal;
//   - per action schema present in both: a precondition literal, an add effect or a delete
//     effect (literals are compared with the schema's parameters by position, so the two
//     models may name them differently);
//   - an action schema present in only one model.
// Applying a difference to the human's model moves it toward the robot's: what the robot's
// model has is added, what only the human's has is removed. With every difference applied,
// P_H has P_R's initial state, goal and action schemas.
// Not differences: action costs and static numeric values (the human's costs are what the
// observers judge a plan by, see minimal_explanation.h), declarations (a predicate or object the
// robot's model has is declared in the human's when a difference needs it), and facts about
// predicates no precondition or goal of either model mentions (they change no plan's
// validity or cost, so no minimal explanation contains them).
//
// Example:
//   std::vector<ModelDifference> d = model_differences(models);
//   ModelPair told = models;
//   apply_difference(d[0], models, told);   // told.human_* is P_H + {d[0]}

#include "design/model/configuration.h"

#include <string>
#include <vector>

namespace envdesign::design {

enum class DifferenceKind { INIT, GOAL, PRECONDITION, ADD_EFFECT, DELETE_EFFECT, ACTION };

struct ModelDifference {
    DifferenceKind kind = DifferenceKind::INIT;
    bool robot_has = true; // true: in P_R only (applying adds it), false: in P_H only
    std::string action;    // the schema, for the schema kinds
    pddl::Literal literal; // INIT, GOAL, schema literals; schema literals name the
                           // parameters by position: "?0", "?1", ...
    std::string text;      // "+init (connected c00 c01)", "-pre move (clear ?to)", ...
};

// Every relevant difference of `models` (all of them with `relevant_only` false: the tests'
// check that the pruning is sound), in a fixed order (kinds as above, then the models'
// order). Throws pddl::ParseError if a schema has different parameter counts in the models.
std::vector<ModelDifference> model_differences(const ModelPair &models, bool relevant_only = true);

// Applies `difference` to told.human_domain / told.human_problem, taking declarations and
// schemas from `models` (the models the difference was computed from).
void apply_difference(const ModelDifference &difference, const ModelPair &models, ModelPair &told);

// The human's model of `models` with the differences `chosen` applied.
ModelPair told_models(const ModelPair &models, const std::vector<ModelDifference> &differences,
                      const std::vector<int> &chosen);
// The same, the human's side alone (the robot's left empty): all the plan validator reads, for
// checks that copy the models many times.
ModelPair told_human_model(const ModelPair &models, const std::vector<ModelDifference> &differences,
                           const std::vector<int> &chosen);

} // namespace envdesign::design
