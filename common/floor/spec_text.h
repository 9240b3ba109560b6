#pragma once
// The text of the files of a floor's design problem (FLOORS.md "The two models"): the one
// domain both models share, each task's robot and human problem, and design.textproto.
//
//   domain.pddl               places, (at ?p), (connected ?from ?to), (length ?from ?to), move
//   tasks/vI-vJ.pddl          the robot's model: (connected p q) for its edges
//   tasks/vI-vJ-human.pddl    the human model: its edges and the sight lines
//   design.textproto          tasks, candidates, weights, distance COST_DIFF

#include "floor_problem.h"

#include <string>

namespace envdesign::floor {

std::string domain_text();

// The problem of task `task` in the robot's model (`human` false) or the human model.
std::string problem_text(const FloorProblem &problem, std::size_t task, bool human);

// Paths of a task's problems, relative to the spec.
std::string robot_problem_path(const FloorTask &task);
std::string human_problem_path(const FloorTask &task);

// design.textproto; `map` is named in its opening comment.
std::string spec_text(const FloorProblem &problem);

// Shortest decimal text that reads back as `value` ("4.2", "0.3333333333333333").
std::string number_text(double value);

} // namespace envdesign::floor
