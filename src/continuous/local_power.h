#pragma once
// Problem 1 for the power basis (z, .., z^n) in local coordinates u = (z - mean) / deviation of
// the distribution. The span of 1, z, .., z^n is that of 1, u, .., u^n, so the feasible
// distributions and G are the same (docs/reference.md §2); but in u a kernel spanning 0.01 in depth
// has columns that differ in their leading digits, where in z (and in double) they differ only in
// the eighth. Rows are orthonormalised over u in [-4, 4] (the distribution's own scale), and the
// continuous method (continuous/continuous.h) solves on the whole interval. What verify's ground
// truth for the Hamburger and Hausdorff closed forms is built on.
#include <span>
#include <vector>

#include "basis/basis.h"
#include "continuous/continuous.h"

namespace mb::lp {

// The basis z, .., z^n under its catalog names (the span local coordinates keep).
Basis power_basis(int degree);

// How many deviations from the mean the seed grid of a local problem reaches: the distribution's
// own scale, where the exchange starts; it adds points beyond where phi needs them.
constexpr double kLocalSeedReach = 8;

struct LocalPowerProblem {
  int degree = 4;         // n: the basis z, .., z^n
  double lo = 0, hi = 1;  // the admissible interval, in z
  int seed_grid =
      kContinuousSeedGrid;  // the finite set the exchange starts from: a uniform grid on [lo, hi]
  std::vector<double> extra_points;  // more points of I, in z (e.g. beyond [lo, hi])
};

struct LocalPowerSolution {
  ContinuousSolution solution;           // G's bracket (the same in z and in u)
  std::vector<double> support, weights;  // the finite optimum's distribution, in z
  // phi as a polynomial in z: sum_k coefficients[k] z^k (k = 0..n), in long double.
  std::vector<long double> coefficients;
  double mean = 0, scale = 1;  // the local coordinate u = (z - mean) / scale
};

LocalPowerSolution solve_power_locally(const LocalPowerProblem& problem,
                                       std::span<const double> depths,
                                       std::span<const double> weights, double zf, Backend& backend,
                                       const ContinuousSettings& settings = {});

}  // namespace mb::lp
