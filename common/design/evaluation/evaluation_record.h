#pragma once
// Task evaluations and robot-cost bounds as durable records (store/record_db.h): their
// names and their bytes. A record's name is the SHA-256 of a text that holds the format
// version, the kind of record, the store's key (models, modifications, distance,
// heuristic: evaluation_store.h), the configuration and the task's key; its value starts
// with the same version. Bumping RECORD_VERSION makes every old record unreachable.

#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/model/ground_key.h"
#include "store/digest.h"

#include <optional>
#include <string>

namespace envdesign::design {

// 2: evaluations carry the EXPLAINING option (TaskExplanation).
// 3: their plans are the A*'s with inherited LM-cut (PlanChoice, plan_cache.h): among plans of
//    equal cost, other plans than version 2's.
inline constexpr int RECORD_VERSION = 3;

enum class RecordKind { EXPLICABILITY, ROBOT_BOUND };

store::Digest record_name(RecordKind kind, const TaskKey &scope, const Configuration &configuration,
                          const TaskKey &task);

// SOLVED and INEXPLICABLE evaluations (LIMIT is never stored).
std::string encode_evaluation(const TaskExplicability &evaluation);
std::optional<TaskExplicability> decode_evaluation(const std::string &bytes); // nullopt: bad

// A ROBOT_BOUND answer (dispatcher.h): c_R* under a configuration, and the task's IE floor
// where one was argued (records written before floors have none), with the explaining robot's
// explanation floor beside it.
struct RobotBound {
    double cost = 0;
    std::optional<double> ie_floor;
    std::optional<int> explanation_floor = std::nullopt;
};
std::string encode_robot_bound(const RobotBound &bound);
std::optional<RobotBound> decode_robot_bound(const std::string &bytes); // nullopt: bad

// The first 128 bits of SHA-256(text): the keys of evaluation_store.h.
TaskKey digest_key(const std::string &text);

} // namespace envdesign::design
