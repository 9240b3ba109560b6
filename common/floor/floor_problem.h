#pragma once
// A floor's design problem, assembled and ready to write: the floor, its two models, the
// tasks left after dropping the unreachable ones, the candidates and the weights. The text
// of each file (spec_text.h) and floor.json (floor_json.h) are made from it.

#include "candidates.h"
#include "floor.h"
#include "floor_graph.h"
#include "tasks.h"

#include <string>
#include <vector>

namespace envdesign::floor {

// The spec's weights (FLOORS.md "Weights").
struct Weights {
    double alpha = 1;
    double beta = 1;
    double kappa = 0;
    int horizon = 1;
    double gamma = 1;
};

struct FloorProblem {
    Floor floor;
    FloorGraph graph;
    double sight_m = 10;
    std::vector<FloorTask> tasks;
    std::vector<Candidate> candidates;
    Weights weights;
};

// The task's probability as the spec gets it: its weight over the sum of the weights;
// nullopt when no task has a weight (all weigh the same).
std::optional<double> task_probability(const FloorProblem &problem, std::size_t task);

} // namespace envdesign::floor
