#pragma once
// The one rule for every number that enters envdesign, from a spec, a flag, a config file,
// the wire or the store: it is finite (INF only where it means "no plan") and within the
// range below, checked where it enters; docs/numbers.md lists the ranges and why.
//
// Why these bounds: within them every term of the objective (design_problem.h) is below
// 1e24 even at the largest horizon, so sums keep their meaning, and the integer program of
// the hitting-set phase sees coefficients CBC handles (it aborted on 1e25). Plan costs are
// the grounder's 32-bit integer costs.
//
//   if (auto why = number_problem(beta, WEIGHT)) fail("beta", "beta " + *why);

#include "design/evaluation/task_evaluation.h"

#include <optional>
#include <string>

namespace envdesign::design {

struct NumberRange {
    double low, high;
};

inline constexpr NumberRange WEIGHT{0, 1e6};  // alpha, beta, kappa, explanation_cost
inline constexpr NumberRange DISCOUNT{0, 1};  // gamma
inline constexpr NumberRange HORIZON{1, 1e9}; // T, an integer
inline constexpr NumberRange MODIFICATION_COST{-1e9, 1e9};
inline constexpr NumberRange TASK_WEIGHT{0, 1e12};       // a task's probability, before normalising
inline constexpr NumberRange TIME_LIMIT_S{0, 1e7};       // about 115 days; 0: no limit
inline constexpr NumberRange PLAN_COST{0, 2147483647.0}; // c_R, c_H: 32-bit ground costs
inline constexpr NumberRange DESIGN_SIZE{0, 1e5};        // max_design_size; 0: no limit
// An explanation floor (explanation_floor.h): a count of model differences.
inline constexpr NumberRange EXPLANATION_FLOOR{0, 1048576};

// nullopt when `value` is finite and in `range`; else "must be a number in [LOW, HIGH]
// (got VALUE)", to follow the name of what was read.
std::optional<std::string> number_problem(double value, NumberRange range);

// A plan cost: in PLAN_COST, or INF ("no plan").
bool valid_plan_cost(double cost);
// An IE: a number >= 0, INF included (no plan, or a gap exp overflows).
bool valid_ie(double ie);
// An explanation floor: an integer in EXPLANATION_FLOOR.
bool valid_explanation_floor(double told);

// The values of an evaluation received (wire) or read back (store): SOLVED or INEXPLICABLE,
// costs valid plan costs, IE not NaN and at least 0, INEXPLICABLE with an infinite IE, a
// SOLVED evaluation with a finite robot cost. nullopt when sound; else why not.
std::optional<std::string> evaluation_problem(const TaskExplicability &evaluation);

} // namespace envdesign::design
