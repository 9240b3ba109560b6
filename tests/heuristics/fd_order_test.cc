#include "heuristics/fd_order.h"

#include <gtest/gtest.h>

namespace envdesign::heuristics {
namespace {

ground::GroundTask named_task(std::vector<std::string> facts) {
    ground::GroundTask task;
    task.fact_names = std::move(facts);
    return task;
}

void add_op(ground::GroundTask &task, std::string name, std::vector<ground::FactId> pre,
            std::vector<ground::FactId> add, std::vector<ground::FactId> del) {
    task.operators.push_back({std::move(name), pre, add, del, 1, 0});
}

// The robot's position causes the visited facts, so its variable comes first; the two
// visited variables are independent and come out in FD's Tarjan order (reverse finishing
// order: the later-sorted one first).
TEST(FdOrder, CausalGraphSourcesFirst) {
    ground::GroundTask task =
        named_task({"(visited l1)", "(at-robot l2)", "(visited l2)", "(at-robot l1)"});
    task.mutex_groups = {{1, 3}};
    add_op(task, "(move l1 l2)", {3}, {1, 2}, {3});
    add_op(task, "(move l2 l1)", {1}, {0, 3}, {1});
    FdOrder order = compute_fd_order(task);
    EXPECT_EQ(order.fact_variable, (std::vector<int>{2, 0, 1, 0}));
    // Values of the robot's variable by name: l1 before l2.
    EXPECT_EQ(order.fact_rank, (std::vector<int>{3, 1, 2, 0}));
}

// Two variables in a cycle: x -> y three times, y -> x once. MaxDAG starts with the
// variable of least incoming weight (x); a goal on x makes edges into x heavy, so y first.
TEST(FdOrder, CyclesBrokenByIncomingWeightAndGoals) {
    ground::GroundTask task = named_task({"(x a)", "(x b)", "(y a)", "(y b)"});
    task.mutex_groups = {{0, 1}, {2, 3}};
    add_op(task, "(o1)", {0, 2}, {3}, {2});
    add_op(task, "(o2)", {0, 3}, {2}, {3});
    add_op(task, "(o3)", {1, 2}, {3}, {2});
    add_op(task, "(o4)", {0, 2}, {1}, {0});
    FdOrder order = compute_fd_order(task);
    EXPECT_EQ(order.fact_variable, (std::vector<int>{0, 0, 1, 1}));
    task.goal = {1};
    order = compute_fd_order(task);
    EXPECT_EQ(order.fact_variable, (std::vector<int>{1, 1, 0, 0}));
}

TEST(FdOrder, OperatorsSortedByName) {
    ground::GroundTask task = named_task({"(p)"});
    add_op(task, "(b x)", {}, {0}, {});
    add_op(task, "(a y)", {}, {0}, {});
    add_op(task, "(a x z)", {}, {0}, {});
    add_op(task, "(a x)", {}, {0}, {});
    FdOrder order = compute_fd_order(task);
    // Byte-wise, as Python sorts "(a x z)" before "(a x)" (' ' < ')').
    EXPECT_EQ(order.operators, (std::vector<ground::OperatorId>{2, 3, 1, 0}));
}

} // namespace
} // namespace envdesign::heuristics
