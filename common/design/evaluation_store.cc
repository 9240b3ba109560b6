#include "design/evaluation_store.h"

#include "design/lifted_key.h"

#include <sstream>

namespace envdesign::design {

TaskKey store_key(const DesignProblem &problem) {
    std::ostringstream text;
    text << lifted_key(problem.robot_domain, {}).hex() << ' '
         << lifted_key(problem.human_domain, {}).hex() << ' '
         << static_cast<int>(problem.weights.distance) << '\n';
    for (const auto &m : problem.modifications) {
        text << m.edits.size() << ':';
        for (const auto &e : m.edits)
            text << static_cast<int>(e.kind) << ',' << static_cast<int>(e.model) << ','
                 << e.action.size() << '#' << e.action << ',' << e.expression.to_string() << ';';
        text << '\n';
    }
    return key_of_text(text.str());
}

TaskKey task_key(const DesignProblem &problem, int task) {
    const DesignTask &t = problem.tasks[task];
    return key_of_text(lifted_key(problem.robot_domain, t.robot_problem).hex() +
                       lifted_key(problem.human_domain, t.human_problem).hex());
}

std::optional<TaskExplicability> EvaluationStore::find(const Configuration &configuration,
                                                       const TaskKey &task) const {
    std::lock_guard lock(mutex_);
    auto it = entries_.find({configuration, task});
    if (it == entries_.end())
        return std::nullopt;
    return it->second;
}

void EvaluationStore::keep(const Configuration &configuration, const TaskKey &task,
                           const TaskExplicability &evaluation) {
    if (evaluation.status == ExplicabilityStatus::LIMIT)
        return;
    std::lock_guard lock(mutex_);
    entries_.insert_or_assign({configuration, task}, evaluation);
}

std::optional<double> EvaluationStore::find_robot_bound(const Configuration &configuration,
                                                        const TaskKey &task) const {
    std::lock_guard lock(mutex_);
    auto it = robot_bounds_.find({configuration, task});
    if (it == robot_bounds_.end())
        return std::nullopt;
    return it->second;
}

void EvaluationStore::keep_robot_bound(const Configuration &configuration, const TaskKey &task,
                                       double bound) {
    std::lock_guard lock(mutex_);
    robot_bounds_.insert_or_assign({configuration, task}, bound);
}

void EvaluationStore::forget(const TaskKey &task) {
    std::lock_guard lock(mutex_);
    std::erase_if(entries_, [&](const auto &e) { return e.first.second == task; });
    std::erase_if(robot_bounds_, [&](const auto &e) { return e.first.second == task; });
}

std::size_t EvaluationStore::size() const {
    std::lock_guard lock(mutex_);
    return entries_.size();
}

std::size_t EvaluationStore::records() const {
    std::lock_guard lock(mutex_);
    return entries_.size() + robot_bounds_.size();
}

} // namespace envdesign::design
