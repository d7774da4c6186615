#pragma once
// Sharp bounds on the blocker search (docs/soft-shadows.md §3): given the moments b of a search
// region, the smallest and largest mean depth of its blockers (the mass in front of z_s) over every
// distribution on the admissible points with those moments. The ratio of two linear functions of
// the distribution is a linear-fractional program; Charnes and Cooper's substitution y = t w,
// t = 1 / (blocker mass) makes it the LP
//   min / max  sum_{z_i < z_s} z_i y_i
//   subject to sum_i y_i b(z_i) = t b,  sum_i y_i = t,  sum_{z_i < z_s} y_i = 1,  y, t >= 0,
// whose optimum is the bound over distributions with blocker mass above 0. Our own engine solves
// the same program by Dinkelbach's iteration instead, on Problem 1's feasible set unchanged: the
// least ratio lambda* is the lambda at which min_w sum_{z_i < z_s} (z_i - lambda) w_i reaches 0.
#include <span>
#include <vector>

#include "lp/problem.h"
#include "lp/solution.h"

namespace mb {

struct BlockerBounds {
  bool solved = false;    // false: the LP solver gave no answer (iteration limit, singular basis)
  bool feasible = false;  // solved and false: no distribution with these moments has blockers
  double lo = 0, hi = 0;  // the smallest and largest mean blocker depth
  int lps = 0;            // LPs solved (Dinkelbach: the steps of both sides)
};

// On the points `points` (e.g. a grid on I and the region's own depths), by GLPK's simplex. The
// rows (1, b) are those of Problem 1's factory, orthonormalised over its grid (lp/problem.h): the
// same feasible set, and powers of z near one another stay apart.
BlockerBounds blocker_bounds(const lp::ProblemFactory& factory, std::span<const double> points,
                             std::span<const double> moments, double zs);

// The same bounds for the distribution (depths, weights) of a search region by Dinkelbach's
// iteration on `backend` (docs/soft-shadows.md §3): I = the factory's grid, the region's depths and
// z_s; each step solves Problem 1's LP with the objective sum_{z_i < z_s} (z_i - lambda) w_i (its
// negative for the largest mean) and moves lambda to the mean blocker depth of the optimum's
// support, until no distribution improves on lambda. Every lambda is the mean of a feasible
// support, so each bound is attained; it is within the LP's certified error over the support's
// blocker mass of the optimum.
BlockerBounds blocker_bounds_dinkelbach(const lp::ProblemFactory& factory,
                                        std::span<const double> depths,
                                        std::span<const double> weights, double zs,
                                        lp::Backend& backend);

}  // namespace mb
