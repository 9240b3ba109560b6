#include "arrivals/redesign.h"

#include "design/model/compilation.h"
#include "design/objective/objective.h"
#include "ground/grounder.h"
#include "pddl/parser.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace envdesign::arrivals {
namespace {

using design::Configuration;
using design::DesignProblem;

constexpr double NOT_KNOWN = std::numeric_limits<double>::quiet_NaN();

// What a spec load checks for its own tasks (spec_checks.h): the pair compiles and grounds,
// and every modification still compiles on it.
void check_task(const DesignProblem &problem, int task) {
    design::ModelPair models = design::base_models(problem, task);
    design::CompiledTask compiled = design::compile_explicable(models);
    ground::ground(compiled.domain, compiled.problem);
    ground::ground(models.human_domain, models.human_problem);
    ground::ground(models.robot_domain, models.robot_problem);
    for (int m = 0; m < static_cast<int>(problem.modifications.size()); ++m)
        design::compile_explicable(design::configured_models(problem, {m}, task));
}

std::string names(const std::vector<std::string> &list) {
    std::string out = "{";
    for (const auto &n : list)
        out += (out.size() > 1 ? ", " : "") + n;
    return out + "}";
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

// Answers every configuration "not evaluated" (LIMIT) at once: behind a StoredEvaluator it
// makes a search that uses what is stored and, where that is not enough, ends not optimal
// instead of planning.
class NoPlanner : public design::Evaluator {
public:
    void evaluate(const std::vector<design::ConfigurationEvaluation> &batch,
                  const design::Deadline &, const design::EvaluationCallbacks &callbacks) override {
        for (const auto &request : batch) {
            design::ConfigurationEvaluation refused = request;
            refused.status = design::EvaluationStatus::LIMIT;
            callbacks.done(std::move(refused));
        }
    }
    design::EvaluatorCounters counters() const override { return {}; }
};

} // namespace

Redesigner::Redesigner(DesignProblem problem, RedesignOptions options)
    : problem_(std::make_unique<DesignProblem>(std::move(problem))), options_(options),
      local_(std::make_unique<design::LocalEvaluator>(*problem_, options.workers, options.planner)),
      store_(options.evaluations, design::store_key(*problem_, options.planner.heuristic)),
      stored_(std::make_unique<design::StoredEvaluator>(*problem_, *local_, store_)),
      no_planner_(std::make_unique<NoPlanner>()),
      store_only_(std::make_unique<design::StoredEvaluator>(*problem_, *no_planner_, store_)) {}

Distribution Redesigner::distribution() const {
    Distribution d;
    for (const auto &t : problem_->tasks)
        d[t.name] = t.probability;
    return d;
}

design::DesignTask parse_new_task(const DesignProblem &problem, const NewTask &task) {
    std::string file = "new-task:" + task.name;
    design::DesignTask t;
    t.name = task.name;
    t.probability = 0;
    const std::string &human = task.human_problem.empty() ? task.problem : task.human_problem;
    t.robot_problem =
        pddl::parse_problem(pddl::read_sexpr(task.problem, file), file, problem.robot_domain);
    // The human's problem may name the robot's domain (it often is the same file).
    t.human_problem =
        pddl::parse_problem(pddl::read_sexpr(human, file + " (human)"), file + " (human)",
                            problem.human_domain, problem.robot_domain.name);
    DesignProblem with = problem; // checked in a copy: `problem` stays as it is
    with.tasks.push_back(t);
    check_task(with, static_cast<int>(with.tasks.size()) - 1);
    return t;
}

std::optional<std::string> Redesigner::add_task(const NewTask &task) {
    try {
        problem_->tasks.push_back(parse_new_task(*problem_, task));
    } catch (const pddl::ParseError &e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

void Redesigner::remove_task(const std::string &name) {
    auto &tasks = problem_->tasks;
    auto it =
        std::find_if(tasks.begin(), tasks.end(), [&](const auto &t) { return t.name == name; });
    if (it == tasks.end())
        return;
    store_.forget(design::task_key(*problem_, static_cast<int>(it - tasks.begin())));
    tasks.erase(it);
}

void Redesigner::set_probabilities(const Distribution &d) {
    double total = 0;
    for (const auto &t : problem_->tasks) {
        auto it = d.find(t.name);
        total += it == d.end() ? 0 : it->second;
    }
    if (!(total > 0))
        return; // nothing to weigh by: keep the current probabilities
    for (auto &t : problem_->tasks) {
        auto it = d.find(t.name);
        t.probability = it == d.end() ? 0 : it->second / total;
    }
}

design::DesignRun Redesigner::search(design::Evaluator &evaluator, design::PlanCache *planner) {
    design::RunSettings settings;
    settings.max_design_size = options_.max_design_size;
    settings.time_limit_s = options_.time_limit_s;
    settings.batch_size = 4 * std::max(1, options_.workers);
    design::EvaluatorCounters before = evaluator.counters();
    design::EvaluationLog log(*problem_, evaluator);
    design::DesignRun run = design::run_design(*problem_, log, planner, settings);
    // The evaluator's counters run over every search; report this one's.
    auto &c = run.result.counters.evaluator;
    c.task_evaluations -= before.task_evaluations;
    c.planner_runs -= before.planner_runs;
    c.cache_hits -= before.cache_hits;
    c.groundings_skipped -= before.groundings_skipped;
    c.planner_seconds -= before.planner_seconds;
    return run;
}

Redesign Redesigner::redesign(const Distribution &d, const std::vector<NewTask> &new_tasks) {
    auto start = std::chrono::steady_clock::now();
    long long stored_before = stored_->stored_answers();
    Distribution d_before = distribution();
    std::vector<std::string> added, refused;
    for (const auto &task : new_tasks) {
        if (d_before.count(task.name))
            continue; // known already (a repeat of an earlier request)
        if (auto why = add_task(task))
            refused.push_back(task.name + ": " + *why);
        else
            added.push_back(task.name);
    }
    set_probabilities(d);
    Redesign out;
    try {
        static_cast<design::DesignRun &>(out) = search(*stored_, &local_->planner());
    } catch (const pddl::ParseError &e) {
        if (added.empty())
            throw;
        // A modified model of a new task does not ground: take the new tasks out again.
        for (const auto &name : added) {
            refused.push_back(name + ": " + e.what());
            remove_task(name);
        }
        added.clear();
        set_probabilities(d);
        static_cast<design::DesignRun &>(out) = search(*stored_, &local_->planner());
    }
    out.change = describe(out, d_before, added, refused);
    out.change.stored_answers = stored_->stored_answers() - stored_before;
    out.change.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.result.best)
        current_ = out.result.best;
    return out;
}

std::optional<Redesign> Redesigner::reweigh(const Distribution &d) {
    auto start = std::chrono::steady_clock::now();
    ++reweighs_;
    Distribution d_before = distribution();
    long long stored_before = store_only_->stored_answers();
    set_probabilities(d);
    Redesign out;
    static_cast<design::DesignRun &>(out) = search(*store_only_, nullptr);
    // Not optimal: a configuration it needed was refused (or the deadline passed), so its
    // best is not proven; the design in force stays the one proven for d_before.
    if (!out.result.optimal || !out.result.best) {
        ++reweighs_needing_planning_;
        set_probabilities(d_before);
        return std::nullopt;
    }
    out.change = describe(out, d_before, {}, {});
    out.change.stored_answers = store_only_->stored_answers() - stored_before;
    out.change.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    current_ = out.result.best;
    return out;
}

double Redesigner::objective_of(const Configuration &configuration) const {
    std::vector<design::TaskExplicability> tasks;
    for (int t = 0; t < static_cast<int>(problem_->tasks.size()); ++t) {
        auto e = stored_->find(configuration, t);
        if (!e)
            return NOT_KNOWN;
        tasks.push_back(std::move(*e));
    }
    return design::objective_of(*problem_, design::design_cost(*problem_, configuration), tasks)
        .value;
}

DesignChange Redesigner::describe(const Redesign &redesign, const Distribution &d_before,
                                  const std::vector<std::string> &added,
                                  const std::vector<std::string> &refused) const {
    DesignChange c;
    c.d_before = d_before;
    c.d_after = distribution();
    c.distance = total_variation(c.d_before, c.d_after);
    c.added_tasks = added;
    c.refused_tasks = refused;
    c.planner_runs = redesign.result.counters.evaluator.planner_runs;
    c.evaluated = redesign.result.counters.configurations_evaluated;
    c.objective_before = current_ ? objective_of(current_->ranked.configuration) : NOT_KNOWN;
    c.objective_after = redesign.result.best ? redesign.result.best->objective.value : NOT_KNOWN;
    if (current_)
        c.before = current_->ranked.configuration;
    if (redesign.result.best)
        c.after = redesign.result.best->ranked.configuration;
    c.before_names = design::design_names(*problem_, c.before);
    c.after_names = design::design_names(*problem_, c.after);
    c.changed = current_.has_value() && redesign.result.best && c.before != c.after;
    std::string why = "D " + to_string(c.d_before) + " -> " + to_string(c.d_after) + " (TV " +
                      number(c.distance) + ")";
    if (!added.empty())
        why += ", new tasks " + names(added);
    if (!refused.empty())
        why += ", refused " + std::to_string(refused.size()) + " new task(s)";
    if (!redesign.result.best)
        c.explanation = "no design evaluated in time; " + why;
    else if (!current_)
        c.explanation = "design " + names(c.after_names) + " (objective " +
                        number(c.objective_after) + ") for " + to_string(c.d_after);
    else if (c.changed && std::isnan(c.objective_before)) // some of its tasks were inherited
        c.explanation = "design " + names(c.before_names) + " -> " + names(c.after_names) +
                        ": under the new D the new design (" + number(c.objective_after) +
                        ") ranks before it; " + why;
    else if (c.changed)
        c.explanation = "design " + names(c.before_names) + " -> " + names(c.after_names) +
                        ": under the new D it costs " + number(c.objective_before) +
                        ", the new design " + number(c.objective_after) + "; " + why;
    else
        c.explanation = "design " + names(c.after_names) + " unchanged (objective " +
                        number(c.objective_after) + "); " + why;
    return c;
}

} // namespace envdesign::arrivals
