#pragma once
// An action-level diff of two plans: a longest common subsequence of their actions, the rest
// marked as only in one plan or only in the other. Used to say how the most explicable plan
// differs from the robot's optimal plan and from the plan observers expect.

#include <string>
#include <vector>

namespace envdesign::client {

enum class DiffSide { BOTH, ONLY_FIRST, ONLY_SECOND };

struct DiffStep {
    DiffSide side = DiffSide::BOTH;
    std::string action;
};

// In plan order; removals from `first` come before additions from `second` at each place.
std::vector<DiffStep> plan_diff(const std::vector<std::string> &first,
                                const std::vector<std::string> &second);

// Whether the two plans differ at all.
bool plans_differ(const std::vector<DiffStep> &diff);

} // namespace envdesign::client
