#pragma once
// Problem 1's range over the rounding of its moments (docs/reference.md §2, "Moments with a
// tolerance"; issue 45): raw moments given in double stand for every vector within their box of
// rounding, and for a narrow kernel G moves across that box by far more than the LP's certificate.
// The least G over the box is the box problem's (continuous/moment_box.h) on a grid, and never
// below the centre's dual bound lower - sum |c_j| eps_j (weak duality), which stands for it on the
// continuous interval. The largest is the maximum of a convex function: G is the optimal value of
// a minimisation LP as a function of its right-hand side, hence convex on the moment cone, so over
// the box it peaks at a vertex when every vertex lies in the cone. Vertices outside the cone have
// no distribution; then the maximum over the feasible vertices is a lower estimate of the true
// maximum (`complete` false).
#include <span>

#include "continuous/continuous.h"
#include "lp/problem.h"
#include "lp/solution.h"

namespace mb::lp {

struct MomentRange {
  bool ok = false;  // the centre answered
  double lo = 0, hi = 0;
  int vertices = 0, feasible = 0;  // box vertices; those with a distribution on I
  bool complete() const { return ok && feasible == vertices; }
};

// The range of G over |b_j - moments_j| <= tolerance_j (tolerance from ulp_box) with z_f and the
// factory's discretisation (grid and `points`, or the continuous interval). `centre` is
// factory.from_moments(moments, zf, points), `solved` the caller's solve_discretized of it; each
// vertex is solved with `backend` as it was. At most 2^7 vertices (the certified engine's rows).
MomentRange moment_range(const ProblemFactory& factory, std::span<const double> moments,
                         std::span<const double> tolerance, double zf,
                         std::span<const double> points, const Problem& centre,
                         const ContinuousSolution& solved, Backend& backend);

}  // namespace mb::lp
