#include "spec/spec_checks.h"

#include "design/model/compilation.h"
#include "design/model/configuration.h"
#include "ground/grounder.h"

#include <algorithm>
#include <array>
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

bool problem_edit(EditKind kind) {
    return kind == EditKind::ADD_INIT || kind == EditKind::REMOVE_INIT ||
           kind == EditKind::ADD_GOAL || kind == EditKind::REMOVE_GOAL;
}

bool init_edit(EditKind kind) {
    return kind == EditKind::ADD_INIT || kind == EditKind::REMOVE_INIT;
}

// Each task's models as the spec gives them, copied once: a modification that edits only
// initial states and goals is tried on them in place and undone, since copying every task's
// models for every modification took most of a large floor's loading (294 x 182 copies).
class PristineModels {
public:
    explicit PristineModels(const DesignProblem &problem) : problem_(problem) {}

    ModelPair &task(std::size_t t) {
        if (models_.empty())
            for (std::size_t i = 0; i < problem_.tasks.size(); ++i)
                models_.push_back(base_models(problem_, static_cast<int>(i)));
        return models_[t];
    }
    // After an in-place trial: the lists are back to their sizes, or the task is copied anew.
    void restore(std::size_t t, const std::array<std::size_t, 4> &sizes) {
        if (list_sizes(models_[t]) != sizes)
            models_[t] = base_models(problem_, static_cast<int>(t));
    }
    static std::array<std::size_t, 4> list_sizes(const ModelPair &m) {
        return {m.robot_problem.init.size(), m.robot_problem.goal.size(),
                m.human_problem.init.size(), m.human_problem.goal.size()};
    }

private:
    const DesignProblem &problem_;
    std::vector<ModelPair> models_;
};

// Missing removes are tallied per (edit, model) over the tasks; other errors stop at once.
class ModificationChecker {
public:
    ModificationChecker(const DesignProblem &problem, const Modification &modification,
                        PristineModels &pristine)
        : problem_(problem), modification_(modification), pristine_(pristine) {}

    void check() {
        bool in_place = std::all_of(modification_.edits.begin(), modification_.edits.end(),
                                    [](const Edit &e) { return problem_edit(e.kind); });
        for (std::size_t t = 0; t < problem_.tasks.size(); ++t) {
            if (!in_place) {
                ModelPair models = base_models(problem_, static_cast<int>(t));
                apply_all(models, t, nullptr);
                continue;
            }
            ModelPair &models = pristine_.task(t);
            auto sizes = PristineModels::list_sizes(models);
            std::vector<Undo> undo;
            apply_all(models, t, &undo);
            for (auto it = undo.rbegin(); it != undo.rend(); ++it)
                it->run(models);
            pristine_.restore(t, sizes);
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
    // What one applied edit changed, to take it back: an added atom or goal is the last of
    // its list; a removed one is added again (the order of a list means nothing).
    struct Undo {
        const Edit *edit;
        bool robot;
        std::size_t size_before;

        void run(ModelPair &m) const {
            pddl::Problem &problem = robot ? m.robot_problem : m.human_problem;
            bool init = init_edit(edit->kind);
            std::size_t size = init ? problem.init.size() : problem.goal.size();
            if (size > size_before) {
                if (init)
                    problem.init.pop_back();
                else
                    problem.goal.pop_back();
            } else if (size < size_before) {
                Edit again = *edit;
                again.kind = init ? EditKind::ADD_INIT : EditKind::ADD_GOAL;
                apply_edit(again, robot ? m.robot_domain : m.human_domain, &problem,
                           ApplyMode::LENIENT);
            }
        }
    };

    void apply_all(ModelPair &models, std::size_t t, std::vector<Undo> *undo) {
        for (std::size_t e = 0; e < modification_.edits.size(); ++e) {
            const Edit &edit = modification_.edits[e];
            for (bool robot : {true, false}) {
                if (robot ? !applies_to_robot(edit.model) : !applies_to_human(edit.model))
                    continue;
                pddl::Problem &problem = robot ? models.robot_problem : models.human_problem;
                if (undo)
                    undo->push_back(
                        {&edit, robot,
                         init_edit(edit.kind) ? problem.init.size() : problem.goal.size()});
                apply(edit, e, robot, robot ? models.robot_domain : models.human_domain, problem,
                      t);
            }
        }
    }

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
    PristineModels &pristine_;
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
    PristineModels pristine(problem);
    for (const auto &m : problem.modifications)
        ModificationChecker(problem, m, pristine).check();
    check_predicate_declarations(problem);
}

} // namespace envdesign::spec
