#pragma once
// Task evaluations kept across design searches, by content.
//
// A task's evaluation under a configuration (its most explicable plan, IE, robot cost)
// depends on the models and the distance only: not on D, not on alpha, beta, kappa, gamma or
// T, which only weigh evaluations in the objective (objective.h). So evaluations are stored
// under
//   - a store key (store_key): both domains, every modification's edits in order, and the
//     distance; the configurations' indices mean the same in every problem with that key;
//   - and per entry, the configuration and a task key (task_key): the content of the task's
//     two problems, so a task that comes back under another name, or a spec re-sent with new
//     probabilities or new tasks, finds what was stored.
// Robot-cost bounds (design/evaluation/dispatcher.h) are kept the same way, so that a configuration
// the bounds abandoned once can be abandoned again without a planner.
// One EvaluationStore holds the entries of one store key; its owner keeps one per key (a
// Redesigner has one; the coordinator a map of them, cluster/evaluation_stores.h).
//
// Durable stores: given a RecordDb (store/record_db.h) and a scope (store_key with the
// heuristic), every entry kept is written to the file before keep() returns, and find()
// looks in the file for what memory lacks (evaluation_record.h names the records), so a
// restarted process finds what an earlier one kept. Memory holds what was kept or found
// since; the file is bounded by the RecordDb, memory by the owner (forget, or dropping the
// store). Keys are SHA-256 digests of the models' canonical text (lifted_key.h).
// Thread-safe.

#include "design/behaviour/explicability.h"
#include "design/evaluation/evaluation_record.h"
#include "design/model/configuration.h"
#include "design/model/ground_key.h"

#include "heuristics/heuristic.h"
#include "store/record_db.h"

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

namespace envdesign::design {

TaskKey store_key(const DesignProblem &problem);
// The store key of evaluations made with `heuristic` (it picks among plans of equal cost,
// so its plans are its own): the scope of a durable store.
TaskKey store_key(const DesignProblem &problem, heuristics::HeuristicKind heuristic);
TaskKey task_key(const DesignProblem &problem, int task);

class EvaluationStore {
public:
    EvaluationStore() = default; // in memory only
    // Backed by `db` (shared with other scopes); `scope` is store_key(problem, heuristic).
    EvaluationStore(std::shared_ptr<store::RecordDb> db, const TaskKey &scope)
        : db_(std::move(db)), scope_(scope) {}

    std::optional<TaskExplicability> find(const Configuration &configuration,
                                          const TaskKey &task) const;
    // Keeps SOLVED and INEXPLICABLE answers; LIMIT says nothing and is not kept.
    void keep(const Configuration &configuration, const TaskKey &task,
              const TaskExplicability &evaluation);
    // The robot's optimal cost under a configuration (a lower bound the search uses to
    // abandon configurations early; INF: the robot has no plan), with the task's IE floor.
    std::optional<RobotBound> find_robot_bound(const Configuration &configuration,
                                               const TaskKey &task) const;
    void keep_robot_bound(const Configuration &configuration, const TaskKey &task,
                          const RobotBound &bound);
    // Forgets every evaluation and bound of one task, in memory (records in the file stay
    // true: they are named by content).
    void forget(const TaskKey &task);
    // The configurations with an evaluation in memory for every one of `tasks`, at most
    // `limit` of them.
    std::vector<Configuration> configurations_with(const std::vector<TaskKey> &tasks,
                                                   std::size_t limit) const;
    std::size_t size() const;    // evaluations in memory
    std::size_t records() const; // evaluations and bounds in memory
    bool durable() const { return db_ != nullptr; }

private:
    std::shared_ptr<store::RecordDb> db_;
    TaskKey scope_;
    mutable std::mutex mutex_;
    // Mutable: find() copies what it read from the file here.
    mutable std::map<std::pair<Configuration, TaskKey>, TaskExplicability> entries_;
    mutable std::map<std::pair<Configuration, TaskKey>, RobotBound> robot_bounds_;
};

} // namespace envdesign::design
