#include "continuous/moment_range.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "continuous/discretized.h"
#include "continuous/moment_box.h"

namespace mb::lp {

namespace {

// A lower bound on G over the whole box from the centre's dual function phi = c_0 + sum c_j b_j:
// phi <= step on I up to the certificate's violation, so by weak duality every b has
// G(b) >= c_0 + sum c_j b_j - violation >= lower(centre) - sum |c_j| eps_j.
double dual_minimum(const ProblemFactory& factory, const ContinuousSolution& centre,
                    std::span<const double> tolerance) {
  std::vector<long double> c = centre.coefficients;
  if (c.empty()) c = factory.raw_coefficients(centre.finite.duals);
  const double lower =
      factory.discretization().continuous ? centre.lower : centre.finite.G - kCertifiedError;
  long double spread = 0;
  for (size_t j = 0; j < tolerance.size() && j + 1 < c.size(); ++j)
    spread += std::abs(c[j + 1]) * tolerance[j];
  return lower - double(spread);
}

}  // namespace

MomentRange moment_range(const ProblemFactory& factory, std::span<const double> moments,
                         std::span<const double> tolerance, double zf,
                         std::span<const double> points, const Problem& centre_problem,
                         const ContinuousSolution& centre, Backend& backend) {
  MomentRange r;
  const size_t m = moments.size();
  if (m > 7 || !centre.ok()) return r;
  // The least G: the box problem's on a grid; on the continuous interval, whose box problem
  // needs a distribution within a few ulps of raw moments that GLPK cannot certify for a narrow
  // kernel, the dual bound (a lower estimate of the minimum, never above it).
  r.lo = dual_minimum(factory, centre, tolerance);
  if (!factory.discretization().continuous) {
    const MomentBoxAnswer box = solve_moment_box(factory, centre_problem, tolerance);
    if (box.status == ProblemStatus::Optimal) r.lo = std::max(r.lo, box.G);
  }
  // The largest G: at a vertex of the box (convexity), each vertex solved as the centre is (on
  // the continuous interval the upper end of its bracket, a distribution's value).
  r.vertices = 1 << m;
  r.hi = centre.finite.G;
  std::vector<double> vertex(m);
  for (int v = 0; v < r.vertices; ++v) {
    for (size_t j = 0; j < m; ++j)
      vertex[j] = moments[j] + ((v >> j) & 1 ? tolerance[j] : -tolerance[j]);
    Problem p = factory.from_moments(vertex, zf, points);
    const ContinuousSolution s = solve_discretized(factory, p, backend);
    if (!s.ok()) continue;
    ++r.feasible;
    r.hi = std::max(r.hi, s.finite.G);
  }
  r.ok = true;
  return r;
}

}  // namespace mb::lp
