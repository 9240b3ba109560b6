#pragma once
// Edits: the atomic changes a design modification makes to a lifted model (SPEC.md,
// "Design problem file"). An edit targets the robot's model, the human's model or both;
// it changes the domain (predicates, action schemas) or the problem (init, goal).
//
// An Edit keeps its text as an S-expression and is checked against the model it is applied
// to, so one parsed edit serves every task. Applying is either STRICT (the spec is being
// validated: a remove of something absent is an error) or LENIENT (a configuration is being
// built: two modifications may remove the same atom, the second is a no-op).
//
// Example:
//   Edit e = parse_edit_text(EditKind::REMOVE_INIT, Model::HUMAN, "(connected c00 c01)", where);
//   apply_edit(e, human_domain, human_problem, ApplyMode::STRICT);  // throws pddl::ParseError

#include "pddl/sexpr.h"
#include "pddl/task.h"

#include <string>

namespace envdesign::design {

enum class Model { BOTH, ROBOT, HUMAN };

enum class EditKind {
    ADD_INIT,
    REMOVE_INIT,
    ADD_GOAL,
    REMOVE_GOAL,
    ADD_PREDICATE,
    ADD_PRECONDITION,
    REMOVE_PRECONDITION,
    ADD_EFFECT,
    REMOVE_EFFECT,
    REMOVE_ACTION,
};

struct Edit {
    EditKind kind = EditKind::ADD_INIT;
    Model model = Model::BOTH;
    std::string action;      // schema name, for the schema edits and REMOVE_ACTION
    pddl::SExpr expression;  // the atom, literal, declaration or ground action; for
                             // REMOVE_ACTION of a whole schema a symbol
    pddl::Location location; // where the edit is written (the spec file)
};

enum class ApplyMode { STRICT, LENIENT };

// Thrown in STRICT mode when an edit removes something the model does not have; the spec
// reader tolerates it in some tasks, not in all.
class NotPresentError : public pddl::ParseError {
public:
    using pddl::ParseError::ParseError;
};

// Reads the edit's text; throws pddl::ParseError at `where` when it is not an
// S-expression of the right shape. Names are checked only when the edit is applied.
Edit parse_edit_text(EditKind kind, Model model, const std::string &action, const std::string &text,
                     const pddl::Location &where);

// Applies `edit` to one model. `problem` may be null for a domain-only check. Throws
// pddl::ParseError (at the edit's location) for an unknown action, predicate, object or
// parameter, a wrong arity, and, in STRICT mode, a remove of something that is not there
// or a predicate declared twice.
void apply_edit(const Edit &edit, pddl::Domain &domain, pddl::Problem *problem, ApplyMode mode);

bool applies_to_robot(Model model);
bool applies_to_human(Model model);
std::string edit_kind_name(EditKind kind);
// An edit's literal as written: (not (p ?x a)) -> p(?x, a) negated. Names are not checked.
pddl::Literal as_literal(const pddl::SExpr &e);

} // namespace envdesign::design
