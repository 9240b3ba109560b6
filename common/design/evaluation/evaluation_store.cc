#include "design/evaluation/evaluation_store.h"

#include "design/evaluation/evaluation_record.h"
#include "design/model/lifted_key.h"

#include <algorithm>
#include <sstream>

namespace envdesign::design {

TaskKey store_key(const DesignProblem &problem) {
    std::ostringstream text;
    text << "envdesign store key " << RECORD_VERSION << '\n'
         << lifted_text(problem.robot_domain, {}) << "\n--\n"
         << lifted_text(problem.human_domain, {}) << "\n--\n"
         << static_cast<int>(problem.weights.distance) << ' '
         << static_cast<int>(problem.weights.behaviour) << '\n';
    for (const auto &m : problem.modifications) {
        text << m.edits.size() << ':';
        for (const auto &e : m.edits)
            text << static_cast<int>(e.kind) << ',' << static_cast<int>(e.model) << ','
                 << e.action.size() << '#' << e.action << ',' << e.expression.to_string() << ';';
        text << '\n';
    }
    return digest_key(text.str());
}

TaskKey store_key(const DesignProblem &problem, heuristics::HeuristicKind heuristic) {
    return digest_key(store_key(problem).hex() + " heuristic " +
                      std::to_string(static_cast<int>(heuristic)));
}

TaskKey task_key(const DesignProblem &problem, int task) {
    const DesignTask &t = problem.tasks[task];
    return digest_key("envdesign task key " + std::to_string(RECORD_VERSION) + "\n" +
                      lifted_text(problem.robot_domain, t.robot_problem) + "\n--\n" +
                      lifted_text(problem.human_domain, t.human_problem));
}

std::optional<TaskExplicability> EvaluationStore::find(const Configuration &configuration,
                                                       const TaskKey &task) const {
    std::lock_guard lock(mutex_);
    auto it = entries_.find({configuration, task});
    if (it != entries_.end())
        return it->second;
    if (!db_)
        return std::nullopt;
    store::Digest name = record_name(RecordKind::EXPLICABILITY, scope_, configuration, task);
    auto bytes = db_->get(name);
    auto evaluation = bytes ? decode_evaluation(*bytes) : std::nullopt;
    if (bytes && !evaluation)
        db_->reject(name); // unusable values: planned again, never used
    if (evaluation)
        entries_.emplace(std::make_pair(configuration, task), *evaluation);
    return evaluation;
}

void EvaluationStore::keep(const Configuration &configuration, const TaskKey &task,
                           const TaskExplicability &evaluation) {
    if (evaluation.status == ExplicabilityStatus::LIMIT)
        return;
    std::lock_guard lock(mutex_);
    auto key = std::make_pair(configuration, task);
    // In memory already: written (or read) before. Written first, so that what memory
    // holds (and the search uses) is in the file.
    if (db_ && !entries_.count(key))
        db_->put(record_name(RecordKind::EXPLICABILITY, scope_, configuration, task),
                 encode_evaluation(evaluation));
    entries_.insert_or_assign(key, evaluation);
}

std::optional<RobotBound> EvaluationStore::find_robot_bound(const Configuration &configuration,
                                                            const TaskKey &task) const {
    std::lock_guard lock(mutex_);
    auto it = robot_bounds_.find({configuration, task});
    if (it != robot_bounds_.end())
        return it->second;
    if (!db_)
        return std::nullopt;
    store::Digest name = record_name(RecordKind::ROBOT_BOUND, scope_, configuration, task);
    auto bytes = db_->get(name);
    auto bound = bytes ? decode_robot_bound(*bytes) : std::nullopt;
    if (bytes && !bound)
        db_->reject(name);
    if (bound)
        robot_bounds_.emplace(std::make_pair(configuration, task), *bound);
    return bound;
}

void EvaluationStore::keep_robot_bound(const Configuration &configuration, const TaskKey &task,
                                       const RobotBound &bound) {
    std::lock_guard lock(mutex_);
    auto key = std::make_pair(configuration, task);
    if (db_ && !robot_bounds_.count(key))
        db_->put(record_name(RecordKind::ROBOT_BOUND, scope_, configuration, task),
                 encode_robot_bound(bound));
    robot_bounds_.insert_or_assign(key, bound);
}

void EvaluationStore::forget(const TaskKey &task) {
    std::lock_guard lock(mutex_);
    std::erase_if(entries_, [&](const auto &e) { return e.first.second == task; });
    std::erase_if(robot_bounds_, [&](const auto &e) { return e.first.second == task; });
}

std::vector<Configuration> EvaluationStore::configurations_with(const std::vector<TaskKey> &tasks,
                                                                std::size_t limit) const {
    std::lock_guard lock(mutex_);
    std::vector<Configuration> out;
    const Configuration *last = nullptr;
    // Entries are ordered by configuration first: count each configuration's tasks in a run.
    std::size_t found = 0;
    auto close = [&] {
        if (last && found == tasks.size() && out.size() < limit)
            out.push_back(*last);
    };
    for (const auto &[key, evaluation] : entries_) {
        if (!last || key.first != *last) {
            close();
            last = &key.first;
            found = 0;
        }
        found += std::find(tasks.begin(), tasks.end(), key.second) != tasks.end();
    }
    close();
    return out;
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
