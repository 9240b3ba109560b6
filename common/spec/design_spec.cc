#include "spec/design_spec.h"

#include "design/model/numbers.h"
#include "pddl/parser.h"
#include "spec/spec_checks.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace envdesign::spec {
namespace {

using design::DesignProblem;
using design::DesignTask;
using design::Distance;
using design::Modification;
using design::ObjectiveWeights;
using design::RobotBehaviour;
using pddl::ParseError;

RobotBehaviour behaviour_from_proto(proto::DesignProblem::RobotBehaviour behaviour) {
    switch (behaviour) {
    case proto::DesignProblem::COST_OPTIMAL:
        return RobotBehaviour::COST_OPTIMAL;
    case proto::DesignProblem::COST_OPTIMAL_BEST_CASE:
        return RobotBehaviour::COST_OPTIMAL_BEST_CASE;
    case proto::DesignProblem::EXPLAINING:
        return RobotBehaviour::EXPLAINING;
    default:
        return RobotBehaviour::EXPLICABLE;
    }
}

class Loader {
public:
    Loader(const SpecFile &spec, const FileSource &files)
        : spec_(spec), m_(spec.message), files_(files) {}

    DesignProblem load(Checks checks) {
        problem_.file = spec_.path;
        load_domains();
        load_tasks();
        load_weights();
        load_modifications();
        if (checks == Checks::FULL)
            check_design_problem(problem_, spec_);
        return std::move(problem_);
    }

private:
    [[noreturn]] void fail(const std::string &field, const std::string &message) const {
        throw ParseError(spec_.at(field), message);
    }

    SourceFile read(const std::string &field, const std::string &path) const {
        if (path.empty())
            fail(field, "'" + field + "' is required");
        try {
            return files_.read(path, field);
        } catch (const MissingFile &e) {
            fail(field, e.what());
        }
    }

    // A PDDL error names the PDDL file; the note says which line of the spec led there.
    template <typename Load> auto load_pddl(const std::string &field, Load load) const {
        try {
            return load();
        } catch (const ParseError &e) {
            throw ParseError(e.location(), e.message() + "\n" + spec_.at(field).to_string() +
                                               ": note: in the file named by " + field);
        }
    }

    void load_domains() {
        SourceFile robot = read("robot_domain", m_.robot_domain());
        problem_.robot_domain = load_pddl(
            "robot_domain", [&] { return pddl::parse_domain_text(robot.content, robot.name); });
        if (m_.human_domain().empty()) {
            problem_.human_domain = problem_.robot_domain;
            return;
        }
        SourceFile human = read("human_domain", m_.human_domain());
        problem_.human_domain = load_pddl(
            "human_domain", [&] { return pddl::parse_domain_text(human.content, human.name); });
    }

    void load_tasks() {
        if (m_.task_size() == 0)
            fail("", "the design problem has no task");
        std::set<std::string> names;
        double total = 0;
        for (int i = 0; i < m_.task_size(); ++i) {
            const auto &t = m_.task(i);
            std::string at = "task[" + std::to_string(i) + "]";
            if (t.name().empty())
                fail(at, "a task needs a name");
            if (!names.insert(t.name()).second)
                fail(at + ".name", "duplicate task name '" + t.name() + "'");
            DesignTask task;
            task.name = t.name();
            task.probability = t.has_probability() ? t.probability() : 1.0;
            if (auto why = design::number_problem(task.probability, design::TASK_WEIGHT))
                fail(at + ".probability", "the probability of task '" + t.name() + "' " + *why);
            total += task.probability;
            SourceFile file = read(at + ".problem", t.problem());
            task.robot_problem = load_pddl(at + ".problem", [&] {
                return pddl::parse_problem_text(file.content, file.name, problem_.robot_domain);
            });
            std::string human_field =
                at + (t.human_problem().empty() ? ".problem" : ".human_problem");
            SourceFile human_file =
                t.human_problem().empty() ? file : read(human_field, t.human_problem());
            task.human_problem = load_pddl(human_field, [&] {
                return pddl::parse_problem_text(human_file.content, human_file.name,
                                                problem_.human_domain, problem_.robot_domain.name);
            });
            if (!t.human_problem().empty())
                if (auto warning = goal_warning(i, task))
                    problem_.warnings.push_back(*warning);
            problem_.tasks.push_back(std::move(task));
        }
        if (total <= 0)
            fail("task[0].probability", "the task probabilities sum to zero");
        for (auto &task : problem_.tasks)
            task.probability /= total;
        if (auto warning = probability_warning(spec_))
            problem_.warnings.push_back(*warning);
    }

    // Two problems of one task with different goals are most often a copy not brought up to
    // date: observers would then be judged on another task than the robot does.
    std::optional<std::string> goal_warning(int i, const DesignTask &task) const {
        auto goal = [](const pddl::Problem &p) {
            std::vector<std::string> literals;
            for (const auto &literal : p.goal)
                literals.push_back(literal.to_string());
            std::sort(literals.begin(), literals.end());
            return literals;
        };
        std::vector<std::string> robot = goal(task.robot_problem);
        std::vector<std::string> human = goal(task.human_problem);
        if (robot == human)
            return std::nullopt;
        auto shown = [](const std::vector<std::string> &literals) {
            std::string text = "(and";
            for (const auto &l : literals)
                text += " " + l;
            return text + ")";
        };
        std::string at = "task[" + std::to_string(i) + "].human_problem";
        return spec_.at(at).to_string() + ": warning: the two problems of task '" + task.name +
               "' have different goals: " + shown(robot) + " in the robot's (" +
               m_.task(i).problem() + "), " + shown(human) + " in the observers' (" +
               m_.task(i).human_problem() + ")";
    }

    void load_weights() {
        ObjectiveWeights &w = problem_.weights;
        // Every number in its range (design/model/numbers.h), named where it is.
        auto number = [&](bool has, double value, double fallback, const char *field,
                          design::NumberRange range) {
            double v = has ? value : fallback;
            if (auto why = design::number_problem(v, range))
                fail(field, std::string(field) + " " + *why);
            return v;
        };
        auto weight = [&](bool has, double value, const char *field) {
            return number(has, value, 1, field, design::WEIGHT);
        };
        w.alpha = weight(m_.has_alpha(), m_.alpha(), "alpha");
        w.beta = weight(m_.has_beta(), m_.beta(), "beta");
        w.kappa = weight(m_.has_kappa(), m_.kappa(), "kappa");
        w.gamma = number(m_.has_gamma(), m_.gamma(), 1, "gamma", design::DISCOUNT);
        w.horizon =
            static_cast<int>(number(m_.has_horizon(), m_.horizon(), 1, "horizon", design::HORIZON));
        w.distance = m_.distance() == proto::DesignProblem::COST_DIFF ? Distance::COST_DIFF
                                                                      : Distance::EXP_COST_DIFF;
        w.behaviour = behaviour_from_proto(m_.robot_behaviour());
        w.explanation_cost =
            weight(m_.has_explanation_cost(), m_.explanation_cost(), "explanation_cost");
        problem_.max_design_size = static_cast<int>(
            number(true, m_.max_design_size(), 0, "max_design_size", design::DESIGN_SIZE));
        problem_.time_limit_s =
            number(true, m_.time_limit_s(), 0, "time_limit_s", design::TIME_LIMIT_S);
    }

    void load_modifications() {
        std::set<std::string> names;
        for (int i = 0; i < m_.modification_size(); ++i) {
            const auto &m = m_.modification(i);
            std::string at = "modification[" + std::to_string(i) + "]";
            if (m.name().empty())
                fail(at, "a modification needs a name");
            if (!names.insert(m.name()).second)
                fail(at + ".name", "duplicate modification name '" + m.name() + "'");
            if (auto why = design::number_problem(m.cost(), design::MODIFICATION_COST))
                fail(at + ".cost", "the cost of modification '" + m.name() + "' " + *why);
            Modification modification{m.name(), m.cost(), {}};
            for (int j = 0; j < m.edit_size(); ++j)
                modification.edits.push_back(
                    edit_from_proto(m.edit(j), at + ".edit[" + std::to_string(j) + "]", spec_));
            problem_.modifications.push_back(std::move(modification));
        }
    }

    const SpecFile &spec_;
    const proto::DesignProblem &m_;
    const FileSource &files_;
    DesignProblem problem_;
};

} // namespace

// Probabilities that do not sum to 1 are most often a typo: say what was made of them.
std::optional<std::string> probability_warning(const SpecFile &spec) {
    double total = 0;
    bool written = false; // a task gives its probability (else all weigh the same, silently)
    for (const auto &t : spec.message.task()) {
        double p = t.has_probability() ? t.probability() : 1.0;
        if (!(p >= 0) || !std::isfinite(p))
            return std::nullopt; // bad input, not a warning
        total += p;
        written = written || t.has_probability();
    }
    if (!written || !(total > 0) || std::abs(total - 1) <= 1e-9)
        return std::nullopt;
    std::ostringstream text;
    text << spec.at("task[0].probability").to_string() << ": warning: the task "
         << "probabilities sum to " << total << ", not 1; they were normalised to";
    const char *separator = " ";
    for (const auto &t : spec.message.task()) {
        text << separator << t.name() << " "
             << (t.has_probability() ? t.probability() : 1.0) / total;
        separator = ", ";
    }
    return text.str();
}

design::DesignProblem load_design_problem(const SpecFile &spec, const FileSource &files,
                                          Checks checks) {
    return Loader(spec, files).load(checks);
}

design::DesignProblem load_design_problem(const SpecFile &spec) {
    return load_design_problem(spec, DiskFiles(spec.path));
}

design::DesignProblem load_design_problem(const std::string &spec_path) {
    return load_design_problem(read_spec_file(spec_path));
}

} // namespace envdesign::spec
