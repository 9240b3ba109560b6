#pragma once
// Content addresses of ground tasks. Two configurations often ground to the very same task
// (a barrier on a passage no plan uses, a human-only edit seen from the robot's side), and
// then the planner's answer is the same: canonicalize() puts a GroundTask in a form that
// depends only on its content (facts and operators ordered by name), and key_of() hashes
// that form. The design engine solves the canonical task, so an answer depends on the key
// alone, whichever configuration asked first.

#include "ground/ground_task.h"

#include <cstdint>
#include <functional>
#include <string>

namespace envdesign::design {

// 128 bits: the chance that two of a million distinct tasks collide is about 1e-27.
struct TaskKey {
    std::uint64_t high = 0;
    std::uint64_t low = 0;

    bool operator==(const TaskKey &o) const { return high == o.high && low == o.low; }
    bool operator<(const TaskKey &o) const { return high != o.high ? high < o.high : low < o.low; }
    std::string hex() const;
};

struct TaskKeyHash {
    std::size_t operator()(const TaskKey &k) const { return static_cast<std::size_t>(k.low); }
};

// Facts sorted by name (ties by old id), operators by (name, cost, secondary cost), every
// fact list and mutex group sorted; the same task content gives the same result.
ground::GroundTask canonicalize(const ground::GroundTask &task);

// Hash of the serialized task: names, operators, costs, initial state, goal, mutex groups
// and the cost flag. Call it on a canonical task.
TaskKey key_of(const ground::GroundTask &task);

// The same 128-bit hash of any text (lifted_key.h hashes a lifted model with it).
TaskKey key_of_text(const std::string &text);

} // namespace envdesign::design
