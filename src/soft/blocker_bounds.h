#pragma once
// Sharp bounds on the blocker search (docs/soft-shadows.md §3): given the moments b of a search
// region, the smallest and largest mean depth of its blockers (the mass in front of z_s) over every
// distribution on the admissible points with those moments. The ratio of two linear functions of
// the distribution is a linear-fractional program; Charnes and Cooper's substitution y = t w,
// t = 1 / (blocker mass) makes it the LP
//   min / max  sum_{z_i < z_s} z_i y_i
//   subject to sum_i y_i b(z_i) = t b,  sum_i y_i = t,  sum_{z_i < z_s} y_i = 1,  y, t >= 0,
// whose optimum is the bound over distributions with blocker mass above 0.
#include <span>
#include <vector>

#include "lp/problem.h"

namespace mb {

struct BlockerBounds {
  bool solved = false;    // false: GLPK gave no answer (iteration limit, singular basis)
  bool feasible = false;  // solved and false: no distribution with these moments has blockers
  double lo = 0, hi = 0;  // the smallest and largest mean blocker depth
};

// On the points `points` (e.g. a grid on I and the region's own depths), by GLPK's simplex. The
// rows (1, b) are those of Problem 1's factory, orthonormalised over its grid (lp/problem.h): the
// same feasible set, and powers of z near one another stay apart.
BlockerBounds blocker_bounds(const lp::ProblemFactory& factory, std::span<const double> points,
                             std::span<const double> moments, double zs);

}  // namespace mb
