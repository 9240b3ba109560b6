#include "design/evaluation/stored_evaluator.h"

#include <map>

namespace envdesign::design {

StoredEvaluator::StoredEvaluator(const DesignProblem &problem, Evaluator &inner,
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

std::optional<TaskExplicability> StoredEvaluator::find(const Configuration &configuration,
                                                       int task) {
    return store_.find(configuration, key(task));
}

void StoredEvaluator::keep_task(const Configuration &configuration, int task,
                                const TaskExplicability &evaluation) {
    store_.keep(configuration, key(task), evaluation);
}

void StoredEvaluator::keep_robot_bound(const Configuration &configuration, int task,
                                       const RobotBound &bound) {
    store_.keep_robot_bound(configuration, key(task), bound);
}

// What the store adds to what the search already knows (status COMPLETE when every task
// is known).
std::vector<Configuration> StoredEvaluator::known_configurations(std::size_t limit) {
    std::vector<TaskKey> keys;
    for (int t = 0; t < static_cast<int>(problem_.tasks.size()); ++t)
        keys.push_back(key(t));
    return store_.configurations_with(keys, limit);
}

ConfigurationEvaluation StoredEvaluator::from_store(const ConfigurationEvaluation &request) {
    ConfigurationEvaluation e = request;
    int tasks = static_cast<int>(problem_.tasks.size());
    e.tasks.resize(tasks);
    e.robot_cost_bounds.resize(tasks);
    e.ie_floors.resize(tasks);
    e.explanation_floors.resize(tasks);
    e.status = EvaluationStatus::COMPLETE;
    for (int t = 0; t < tasks; ++t) {
        if (!e.tasks[t])
            e.tasks[t] = find(e.configuration, t);
        // The witness search bounds supersets with it; a bound the search inherited
        // (rising_bounds.h) gives way to a stored one at least as great, with its floor.
        if (!e.ie_floors[t]) {
            auto bound = store_.find_robot_bound(e.configuration, key(t));
            if (bound && (!e.robot_cost_bounds[t] || *e.robot_cost_bounds[t] <= bound->cost)) {
                e.robot_cost_bounds[t] = bound->cost;
                e.ie_floors[t] = bound->ie_floor;
                e.explanation_floors[t] = bound->explanation_floor;
            }
        }
        if (!e.tasks[t])
            e.status = EvaluationStatus::LIMIT; // not complete
    }
    return e;
}

// Stores what `evaluation` holds beyond `request`: inherited tasks are not stored again.
void StoredEvaluator::keep(const ConfigurationEvaluation &evaluation,
                           const ConfigurationEvaluation &request) {
    int tasks = static_cast<int>(std::min(evaluation.tasks.size(), problem_.tasks.size()));
    auto given = [&](const auto &known, int t) {
        return t < static_cast<int>(known.size()) && known[t].has_value();
    };
    for (int t = 0; t < tasks; ++t) {
        if (evaluation.tasks[t] && !given(request.tasks, t))
            store_.keep(evaluation.configuration, key(t), *evaluation.tasks[t]);
        bool answered = !given(request.robot_cost_bounds, t) ||
                        (given(evaluation.ie_floors, t) && !given(request.ie_floors, t));
        if (given(evaluation.robot_cost_bounds, t) && answered)
            store_.keep_robot_bound(
                evaluation.configuration, key(t),
                {*evaluation.robot_cost_bounds[t],
                 given(evaluation.ie_floors, t) ? evaluation.ie_floors[t] : std::nullopt,
                 given(evaluation.explanation_floors, t) ? evaluation.explanation_floors[t]
                                                         : std::nullopt});
    }
}

void StoredEvaluator::evaluate(const std::vector<ConfigurationEvaluation> &batch,
                               const Deadline &deadline, const EvaluationCallbacks &callbacks) {
    // Complete ones first: they may lower the best objective the partial ones are judged by.
    std::vector<ConfigurationEvaluation> partial;
    std::vector<const ConfigurationEvaluation *> requests;
    for (const auto &request : batch) {
        ConfigurationEvaluation known = from_store(request);
        if (known.status != EvaluationStatus::COMPLETE) {
            partial.push_back(std::move(known));
            requests.push_back(&request);
            continue;
        }
        ++stored_answers_;
        callbacks.done(std::move(known));
    }
    std::vector<ConfigurationEvaluation> missing;
    std::map<Configuration, const ConfigurationEvaluation *> request_of;
    for (std::size_t i = 0; i < partial.size(); ++i) {
        auto &known = partial[i];
        if (!callbacks.abandon || !callbacks.abandon(known)) {
            request_of[known.configuration] = requests[i];
            missing.push_back(std::move(known));
            continue;
        }
        known.status = EvaluationStatus::CUT_OFF;
        ++stored_answers_;
        callbacks.done(std::move(known));
    }
    if (missing.empty())
        return;
    EvaluationCallbacks keeping;
    keeping.abandon = callbacks.abandon;
    keeping.done = [&](ConfigurationEvaluation evaluation) {
        keep(evaluation, *request_of.at(evaluation.configuration));
        callbacks.done(std::move(evaluation));
    };
    inner_.evaluate(missing, deadline, keeping);
}

} // namespace envdesign::design
