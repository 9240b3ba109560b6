#pragma once
// Lower bounds on an optimal cost that never drops when some modifications are added, carried
// to larger configurations. Two such costs:
//   - c_R*, across robot-restricting modifications (witness.h: every edit restricts the robot's
//     model, or the modification only gates, gated_twins.h). The witness search remembers the
//     robot bounds of the configurations it evaluated, and one configuration larger starts from
//     the greatest bound of its subsets that differ by such a modification: the evaluator then
//     solves only the human's model for the task's IE floor. (The exhaustive search, the
//     cross-check, asks for every bound.)
//   - c_H*, across human-restricting ones: the evaluator's floor job skips the human's A* where
//     a subset's c_H* already reaches the robot bound (local_evaluator.h).

#include "design/model/configuration.h"

#include <map>
#include <optional>
#include <vector>

namespace envdesign::design {

class RisingBounds {
public:
    // rising[m]: whether modification m never lowers the cost.
    explicit RisingBounds(std::vector<bool> rising) : rising_(std::move(rising)) {}

    // Keeps per-task bounds of a configuration, with the greater of each known one.
    void remember(const Configuration &configuration,
                  const std::vector<std::optional<double>> &bounds);
    // Raises the unset or lesser entries of `bounds` to those of the configuration's subsets
    // one rising modification smaller.
    void inherit(const Configuration &configuration,
                 std::vector<std::optional<double>> &bounds) const;
    // Configurations with bounds kept.
    std::size_t size() const { return known_.size(); }
    // The subsets of `configuration` one rising modification smaller.
    std::vector<Configuration> parents(const Configuration &configuration) const;

private:
    std::vector<bool> rising_;
    std::map<Configuration, std::vector<std::optional<double>>> known_;
};

} // namespace envdesign::design
