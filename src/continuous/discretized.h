#pragma once
// Problem 1 as the discretisation asks (docs/reference.md §2): the finite LP on the grid ∪ the
// fragment's points, or (Discretization::continuous) the whole interval by the exchange method
// with its certificate (continuous/continuous.h). A power basis z, .., z^n with a known
// distribution is solved in that distribution's local coordinates (continuous/local_power.h), where
// narrow kernels keep their digits. The one entry point of eval's lp: techniques, the sweep, bounds
// and solve.
#include <span>

#include "continuous/continuous.h"

namespace mb::lp {

// `problem` was built by `factory` (from `depths` and `weights` when given); the exchange may
// append points to it. On the grid, the answer is the finite LP's: upper = G and lower = NaN.
ContinuousSolution solve_discretized(const ProblemFactory& factory, Problem& problem,
                                     Backend& backend, std::span<const double> depths = {},
                                     std::span<const double> weights = {});

// n when `basis` is z, z^2, .., z^n in that order; 0 otherwise.
int power_basis_degree(const Basis& basis);

}  // namespace mb::lp
