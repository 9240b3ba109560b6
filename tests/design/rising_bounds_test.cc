// RisingBounds: a configuration starts from the robot bounds of its subsets one
// robot-restricting modification smaller, and from nothing else.

#include "design/search/rising_bounds.h"

#include <gtest/gtest.h>

namespace envdesign::design {
namespace {

using Bounds = std::vector<std::optional<double>>;

TEST(RisingBounds, InheritsOnlyAcrossRobotRestrictingModifications) {
    RisingBounds memory({true, false, true}); // modification 1 may lower c_R*
    memory.remember({}, {10.0, std::nullopt});
    memory.remember({0}, {14.0, 9.0});
    memory.remember({1}, {3.0, 3.0});

    Bounds from_root;
    memory.inherit({2}, from_root);
    EXPECT_EQ(from_root, (Bounds{10.0, std::nullopt}));

    Bounds greatest{12.0, std::nullopt}; // {0, 2} has {0} and {2} below it: {0} is known
    memory.inherit({0, 2}, greatest);
    EXPECT_EQ(greatest, (Bounds{14.0, 9.0}));

    Bounds across_a_lane; // {0, 1} is {1} + 0 (inherits) and {0} + 1 (does not)
    memory.inherit({0, 1}, across_a_lane);
    EXPECT_EQ(across_a_lane, (Bounds{3.0, 3.0}));

    Bounds kept{20.0, 1.0}; // a greater bound already known stays
    memory.inherit({0, 2}, kept);
    EXPECT_EQ(kept, (Bounds{20.0, 9.0}));

    // Remembered again, one task at a time (the evaluator's floor jobs): each keeps its greatest.
    memory.remember({0}, {std::nullopt, 11.0});
    memory.remember({0}, {13.0, std::nullopt});
    Bounds merged;
    memory.inherit({0, 2}, merged);
    EXPECT_EQ(merged, (Bounds{14.0, 11.0}));
}

} // namespace
} // namespace envdesign::design
