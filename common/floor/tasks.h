#pragma once
// The tasks of a floor (FLOORS.md "Tasks"): the robot goes from one place to another. From a
// CSV file `from,to,weight` (places by label or vI), or every ordered pair of distinct named
// places; pairs the robot's lanes cannot connect are dropped with a warning.
//
//   std::vector<FloorTask> tasks = read_tasks_csv("tasks.csv", floor);   // or default_tasks
//   tasks = drop_unreachable(tasks, floor, graph, warnings);

#include "floor.h"
#include "floor_graph.h"

#include <optional>
#include <string>
#include <vector>

namespace envdesign::floor {

// A task's weight, at most: the spec's range for a task's weight (TASK_WEIGHT,
// design/model/numbers.h), so that the sum of MAX_TASKS of them is finite (issue 21: two weights of
// 1.7e308 summed to inf, and every probability written was 0).
inline constexpr double MAX_TASK_WEIGHT = 1e12;

struct FloorTask {
    int from = 0; // vertex numbers
    int to = 0;
    std::optional<double> weight; // as written; none for the default tasks (equal weights)
    std::string name() const { return object_name(from) + "-" + object_name(to); }
};

// The vertex number of the place `text` names: "vI" of a place, else the label of exactly
// one place; nullopt with `why` set otherwise.
std::optional<int> find_place(const Floor &floor, const std::string &text, std::string &why);

// Reads the CSV at `path` (header `from,to,weight`, then one task a row; blank lines
// skipped; no quoting). Throws pddl::ParseError at FILE:LINE:COL for a bad row, an unknown
// place, from = to, a pair given twice, a weight that is not a finite number > 0 and at most
// MAX_TASK_WEIGHT.
std::vector<FloorTask> read_tasks_csv(const std::string &path, const Floor &floor);
std::vector<FloorTask> parse_tasks_csv(const std::string &text, const std::string &path,
                                       const Floor &floor);

// Every ordered pair of distinct named places, by vertex number (from, then to). Throws
// FloorError if there is no named place, or more than MAX_TASKS pairs.
std::vector<FloorTask> default_tasks(const Floor &floor);

// `tasks` without those the robot cannot do; each dropped one adds a warning naming it.
std::vector<FloorTask> drop_unreachable(const std::vector<FloorTask> &tasks, const Floor &floor,
                                        const FloorGraph &graph,
                                        std::vector<std::string> &warnings);

} // namespace envdesign::floor
