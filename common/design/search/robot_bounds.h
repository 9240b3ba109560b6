#pragma once
// c_R* never drops when a robot-restricting modification (witness.h: every edit restricts
// the robot's model, or the modification only gates, gated_twins.h) is added. The witness
// search remembers the robot bounds of the configurations it evaluated, and one configuration
// larger starts from the greatest bound of its subsets that differ by such a modification:
// the evaluator then solves only the human's model for the task's IE floor. (The exhaustive
// search, the cross-check and the explaining robot's fallback, asks for every bound: there a
// full evaluation costs more than the robot's A*, and the exact bound abandons more.)

#include "design/model/configuration.h"

#include <map>
#include <optional>
#include <vector>

namespace envdesign::design {

class RobotBoundMemory {
public:
    // robot_restricting[m]: whether modification m never lowers c_R*.
    explicit RobotBoundMemory(std::vector<bool> robot_restricting)
        : robot_restricting_(std::move(robot_restricting)) {}

    // Keeps the per-task bounds of an evaluated (or abandoned) configuration.
    void remember(const Configuration &configuration,
                  const std::vector<std::optional<double>> &bounds);
    // Raises the unset or lesser entries of `bounds` to those of the configuration's subsets
    // one robot-restricting modification smaller.
    void inherit(const Configuration &configuration,
                 std::vector<std::optional<double>> &bounds) const;

private:
    std::vector<bool> robot_restricting_;
    std::map<Configuration, std::vector<std::optional<double>>> known_;
};

} // namespace envdesign::design
