#pragma once
// The objective's formula (SPEC.md, "The model"), header-only and free of the engine's types
// so that the clients' plots (clients/cpp, which link none of the engine) weigh a design
// point with the very arithmetic the searches use (objective.h):
//   objective = alpha * f_T(E[IE]) + beta * C + kappa * T * E[c_R] + f_T(E[x * |E|]),
//   f_T(x) = x * (1 - gamma^T) / (1 - gamma), and T * x when gamma = 1.

#include <cmath>

namespace envdesign::design::formula {

// f_T(1): (1 - gamma^T) / (1 - gamma), or T when gamma = 1.
inline double discounted_horizon(double gamma, double horizon) {
    if (gamma >= 1)
        return horizon;
    return (1 - std::pow(gamma, horizon)) / (1 - gamma);
}

// The weighted sum of the terms already discounted or multiplied by T (objective.h's
// ObjectiveTerms): inexplicability f_T(E[IE]), design cost C, robot cost T * E[c_R], and the
// explaining robot's f_T(E[x * |E|]) (weight 1: it is a cost in the robot's units).
inline double weighted_sum(double alpha, double beta, double kappa, double inexplicability,
                           double design_cost, double robot_cost, double explanation) {
    return alpha * inexplicability + beta * design_cost + kappa * robot_cost + explanation;
}

} // namespace envdesign::design::formula
