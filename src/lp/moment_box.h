#pragma once
// Problem 1 with moments known only to a tolerance (REFERENCE.md §2, "Moments with a tolerance"):
// minimise the mass in front of z_f over all distributions on the problem's points whose moments
// lie in the box |E[b_j] - b_j| <= eps_j. A boundary moment vector (few atoms) rounded to double
// may lie just outside the moment cone, where the exact LP is infeasible; the box problem is
// feasible whenever the true moments are within eps, and its G is a lower bound for every
// distribution that could have produced the stored moments. Solved by GLPK on the raw rows,
// each scaled by its largest value over the points (our simplex has no bounded rows).
#include <span>
#include <vector>

#include "lp/problem.h"
#include "lp/solution.h"

namespace mb::lp {

struct MomentBoxAnswer {
  ProblemStatus status = ProblemStatus::Unstable;
  double G = 0;
  std::vector<double> support, weights;  // the optimal distribution (points, weights)
  // Infeasible: the smallest t such that a distribution on the points has
  // |E[b_j] - b_j| <= t max(|b_j|, eps_j) for every j, i.e. how far outside the cone b lies,
  // relative to each moment (0 when feasible).
  double relative_distance = 0;
};

// `problem` from factory.from_moments (its points and untransformed moments are used).
MomentBoxAnswer solve_moment_box(const ProblemFactory& factory, const Problem& problem,
                                 std::span<const double> tolerance);

// eps_j = ulps * ulp(|b_j|), at least ulps * ulp of b_j's largest value on the points (a zero
// moment still has the rounding of the sums that made it).
std::vector<double> ulp_box(const ProblemFactory& factory, const Problem& problem, double ulps);

}  // namespace mb::lp
