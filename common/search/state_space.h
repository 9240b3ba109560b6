#pragma once
// The whole reachable state space of a small task, explored once, answers for every
// operator at the same time what an A* search answers for one: the least cost of a plan
// that takes that operator somewhere. (A* needs a flag fact the operator sets and the goal
// requires, and one search per operator.)
//
// Every state reachable from the initial state is registered with its outgoing steps; g is
// the least cost from the initial state (Dijkstra forward), h* the least cost to a goal
// state (Dijkstra on the reversed steps). A plan with a step o from s to s' costs at least
// g(s) + cost(o) + h*(s'), and the cheapest such plan costs exactly that, so the least
// over o's steps is the answer. Costs are primary costs.
//
// Example:
//   auto through = least_cost_through_operators(task, 100000, [] { return false; });
//   if (through) cost_using_o = (*through)[o];   // INF: no plan takes o

#include "ground/ground_task.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace envdesign::search {

// Per operator, the least primary cost of a plan of `task` with a step of it, or INF
// (infinity) where no plan takes it. nullopt when more than `max_states` states (or eight
// times as many steps between them) are reachable, or when `stop` returns true (asked every
// few thousand states). Memory: about 40 bytes per step.
std::optional<std::vector<double>> least_cost_through_operators(const ground::GroundTask &task,
                                                                std::size_t max_states,
                                                                const std::function<bool()> &stop);

} // namespace envdesign::search
