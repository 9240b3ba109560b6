#include "spec/spec_checks.h"

#include "design/compilation.h"
#include "design/configuration.h"
#include "ground/grounder.h"

#include <map>
#include <optional>

namespace envdesign::spec {
namespace {

using design::ApplyMode;
using design::CompiledTask;
using design::DesignProblem;
using design::Edit;
using design::EditKind;
using design::Model;
using design::ModelPair;
using design::Modification;
using design::NotPresentError;

using pddl::ParseError;

Model model_from_proto(proto::Edit::Model model) {
    switch (model) {
    case proto::Edit::ROBOT:
        return Model::ROBOT;
    case proto::Edit::HUMAN:
        return Model::HUMAN;
    default:
        return Model::BOTH;
    }
}

struct KindText {
    EditKind kind;
    std::string field;  // the oneof member, e.g. "add_precondition"
    std::string action; // for the schema edits
    std::string text;
    std::string text_field; // where the text is: "add_init" or "add_effect.literal"
};

KindText kind_text(const proto::Edit &e) {
    auto literal = [](EditKind kind, const std::string &field, const proto::ActionLiteral &a) {
        return KindText{kind, field, a.action(), a.literal(), field + ".literal"};
    };
    auto plain = [](EditKind kind, const std::string &field, const std::string &text) {
        return KindText{kind, field, "", text, field};
    };
    switch (e.kind_case()) {
    case proto::Edit::kAddInit:
        return plain(EditKind::ADD_INIT, "add_init", e.add_init());
    case proto::Edit::kRemoveInit:
        return plain(EditKind::REMOVE_INIT, "remove_init", e.remove_init());
    case proto::Edit::kAddGoal:
        return plain(EditKind::ADD_GOAL, "add_goal", e.add_goal());
    case proto::Edit::kRemoveGoal:
        return plain(EditKind::REMOVE_GOAL, "remove_goal", e.remove_goal());
    case proto::Edit::kAddPredicate:
        return plain(EditKind::ADD_PREDICATE, "add_predicate", e.add_predicate());
    case proto::Edit::kAddPrecondition:
        return literal(EditKind::ADD_PRECONDITION, "add_precondition", e.add_precondition());
    case proto::Edit::kRemovePrecondition:
        return literal(EditKind::REMOVE_PRECONDITION, "remove_precondition",
                       e.remove_precondition());
    case proto::Edit::kAddEffect:
        return literal(EditKind::ADD_EFFECT, "add_effect", e.add_effect());
    case proto::Edit::kRemoveEffect:
        return literal(EditKind::REMOVE_EFFECT, "remove_effect", e.remove_effect());
    case proto::Edit::kRemoveAction:
        return plain(EditKind::REMOVE_ACTION, "remove_action", e.remove_action());
    default:
        return {EditKind::ADD_INIT, "", "", "", ""};
    }
}

std::string model_name(bool robot) { return robot ? "robot" : "human"; }

// Missing removes are tallied per (edit, model) over the tasks; other errors stop at once.
class ModificationChecker {
public:
    ModificationChecker(const DesignProblem &problem, const Modification &modification)
        : problem_(problem), modification_(modification) {}

    void check() {
        for (std::size_t t = 0; t < problem_.tasks.size(); ++t) {
            ModelPair models = base_models(problem_, static_cast<int>(t));
            for (std::size_t e = 0; e < modification_.edits.size(); ++e) {
                const Edit &edit = modification_.edits[e];
                if (applies_to_robot(edit.model))
                    apply(edit, e, true, models.robot_domain, models.robot_problem, t);
                if (applies_to_human(edit.model))
                    apply(edit, e, false, models.human_domain, models.human_problem, t);
            }
        }
        for (const auto &[key, missing] : missing_)
            if (missing.count == problem_.tasks.size())
                throw *missing.first;
    }

private:
    struct Missing {
        std::size_t count = 0;
        std::optional<NotPresentError> first;
    };

    void apply(const Edit &edit, std::size_t index, bool robot, pddl::Domain &domain,
               pddl::Problem &problem, std::size_t task) {
        std::string where = " (in the " + model_name(robot) + " model of task '" +
                            problem_.tasks[task].name + "', modification '" + modification_.name +
                            "')";
        try {
            apply_edit(edit, domain, &problem, ApplyMode::STRICT);
        } catch (const NotPresentError &e) {
            Missing &m = missing_[{index, robot}];
            if (!m.first)
                m.first.emplace(e.location(), e.message() + where);
            ++m.count;
        } catch (const ParseError &e) {
            throw ParseError(e.location(), e.message() + where);
        }
    }

    const DesignProblem &problem_;
    const Modification &modification_;
    std::map<std::pair<std::size_t, bool>, Missing> missing_;
};

// Two modifications that declare the same predicate must agree, or applying both fails.
void check_predicate_declarations(const DesignProblem &problem) {
    std::map<std::string, std::pair<std::string, std::string>> declared; // name -> text, by
    for (const auto &m : problem.modifications) {
        for (const auto &edit : m.edits) {
            if (edit.kind != EditKind::ADD_PREDICATE || !edit.expression.is_list ||
                edit.expression.items.empty())
                continue;
            const std::string &name = edit.expression.items[0].symbol;
            auto [it, inserted] =
                declared.emplace(name, std::pair{edit.expression.to_string(), m.name});
            if (!inserted && it->second.first != edit.expression.to_string())
                throw ParseError(edit.location, "predicate '" + name +
                                                    "' is declared differently by modification '" +
                                                    it->second.second + "'");
        }
    }
}

} // namespace

Edit edit_from_proto(const proto::Edit &edit, const std::string &field, const SpecFile &spec) {
    KindText k = kind_text(edit);
    if (k.field.empty())
        throw ParseError(spec.at(field), "an edit needs exactly one of add_init, remove_init, "
                                         "add_goal, remove_goal, add_predicate, "
                                         "add_precondition, remove_precondition, add_effect, "
                                         "remove_effect, remove_action");
    std::string at = field + "." + k.text_field;
    if (k.text.empty())
        throw ParseError(spec.at(at), edit_kind_name(k.kind) + " needs a value");
    bool schema_edit = k.text_field != k.field;
    if (schema_edit && k.action.empty())
        throw ParseError(spec.at(field + "." + k.field),
                         edit_kind_name(k.kind) + " needs an action");
    return parse_edit_text(k.kind, model_from_proto(edit.model()), k.action, k.text, spec.at(at));
}

void check_design_problem(const DesignProblem &problem, const SpecFile &spec) {
    for (std::size_t t = 0; t < problem.tasks.size(); ++t) {
        ModelPair models = base_models(problem, static_cast<int>(t));
        try {
            // Grounding finds what only it can (an action cost without a value).
            CompiledTask compiled = compile_explicable(models);
            ground::ground(compiled.domain, compiled.problem);
            ground::ground(models.human_domain, models.human_problem);
            ground::ground(models.robot_domain, models.robot_problem);
        } catch (const ParseError &e) {
            throw ParseError(e.location(),
                             e.message() + "\n" +
                                 spec.at("task[" + std::to_string(t) + "]").to_string() +
                                 ": note: while compiling task '" + problem.tasks[t].name + "'");
        }
    }
    for (const auto &m : problem.modifications)
        ModificationChecker(problem, m).check();
    check_predicate_declarations(problem);
}

} // namespace envdesign::spec
