#include "arrivals/stored_evaluator.h"

namespace envdesign::arrivals {

using design::ConfigurationEvaluation;

StoredEvaluator::StoredEvaluator(const design::DesignProblem &problem, design::Evaluator &inner,
                                 EvaluationStore &store)
    : problem_(problem), inner_(inner), store_(store) {}

const TaskKey &StoredEvaluator::key(int task) {
    if (static_cast<int>(task_keys_.size()) <= task)
        task_keys_.resize(task + 1);
    auto &[name, key] = task_keys_[task];
    if (name != problem_.tasks[task].name) { // first use, or the tasks changed
        name = problem_.tasks[task].name;
        key = task_key(problem_, task);
    }
    return key;
}

std::optional<design::TaskExplicability>
StoredEvaluator::find(const design::Configuration &configuration, int task) {
    return store_.find(configuration, key(task));
}

ConfigurationEvaluation StoredEvaluator::from_store(const design::Configuration &configuration) {
    ConfigurationEvaluation e;
    e.configuration = configuration;
    e.status = design::EvaluationStatus::COMPLETE;
    for (int t = 0; t < static_cast<int>(problem_.tasks.size()); ++t) {
        e.tasks.push_back(find(configuration, t));
        e.robot_cost_bounds.push_back(store_.find_robot_bound(configuration, key(t)));
        if (!e.tasks.back())
            e.status = design::EvaluationStatus::LIMIT; // not complete
    }
    return e;
}

void StoredEvaluator::keep(const ConfigurationEvaluation &evaluation) {
    int tasks = static_cast<int>(std::min(evaluation.tasks.size(), problem_.tasks.size()));
    for (int t = 0; t < tasks; ++t) {
        if (evaluation.tasks[t])
            store_.keep(evaluation.configuration, key(t), *evaluation.tasks[t]);
        if (t < static_cast<int>(evaluation.robot_cost_bounds.size()) &&
            evaluation.robot_cost_bounds[t])
            store_.keep_robot_bound(evaluation.configuration, key(t),
                                    *evaluation.robot_cost_bounds[t]);
    }
}

void StoredEvaluator::evaluate(const std::vector<design::Configuration> &batch,
                               const design::Deadline &deadline,
                               const design::EvaluationCallbacks &callbacks) {
    // Complete ones first: they may lower the best objective the partial ones are judged by.
    std::vector<ConfigurationEvaluation> partial;
    for (const auto &configuration : batch) {
        ConfigurationEvaluation known = from_store(configuration);
        if (known.status != design::EvaluationStatus::COMPLETE) {
            partial.push_back(std::move(known));
            continue;
        }
        ++stored_answers_;
        callbacks.done(std::move(known));
    }
    std::vector<design::Configuration> missing;
    for (auto &known : partial) {
        if (!callbacks.abandon || !callbacks.abandon(known)) {
            missing.push_back(known.configuration);
            continue;
        }
        known.status = design::EvaluationStatus::CUT_OFF;
        ++stored_answers_;
        callbacks.done(std::move(known));
    }
    if (missing.empty())
        return;
    design::EvaluationCallbacks keeping;
    keeping.abandon = callbacks.abandon;
    keeping.done = [&](ConfigurationEvaluation evaluation) {
        keep(evaluation);
        callbacks.done(std::move(evaluation));
    };
    inner_.evaluate(missing, deadline, keeping);
}

} // namespace envdesign::arrivals
