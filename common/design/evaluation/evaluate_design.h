#pragma once
// One proposed design evaluated the way the search evaluates designs (`envdesign evaluate`):
// the same Evaluator, the same objective, the empty design beside it as the baseline.

#include "design/search/design_search.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::design {

// A modification name that is not in the problem, or named twice.
class UnknownModification : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// The configuration of `names` (any order; an empty list is the empty design). Throws
// UnknownModification naming the first name that is not a modification, or a repeated one.
Configuration configuration_of(const DesignProblem &problem, const std::vector<std::string> &names);

// The result of evaluating `configuration` (best) and the empty design (baseline) through
// `evaluator`. `optimal` is false; `limit_reached` when the deadline stopped an evaluation
// (then best, or baseline, may be unset).
DesignResult evaluate_design(const DesignProblem &problem, Evaluator &evaluator,
                             const Configuration &configuration, const Deadline &deadline);

} // namespace envdesign::design
