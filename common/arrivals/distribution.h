#pragma once
// A task distribution D: task name -> probability. Sparse (a task not named has probability
// 0) and ordered by name, so that printing and comparing are deterministic.

#include <map>
#include <string>
#include <vector>

namespace envdesign::arrivals {

using Distribution = std::map<std::string, double>;

// Total variation distance: 1/2 * sum over the union of tasks of |p(t) - q(t)|, in [0, 1]
// for two distributions (0: equal, 1: disjoint supports).
double total_variation(const Distribution &p, const Distribution &q);

// `weights` scaled to sum 1; empty when the weights sum to 0 or less. Negative weights are
// invalid input (assert).
Distribution normalized(const Distribution &weights);

// "{pick: 0.9, put: 0.1}" for logs.
std::string to_string(const Distribution &d);

} // namespace envdesign::arrivals
