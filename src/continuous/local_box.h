#pragma once
// Problem 1 over the rounding box of raw power moments, in the moments' own local coordinates
// (docs/reference.md §2, "Moments with a tolerance"; issue 45). A narrow kernel's raw moments
// (z, .., z^n) rounded to double can lie just outside the moment cone, and a box of a few ulps
// around them is beyond what an LP in z resolves: its columns agree in their leading digits. In
// u = (z - mean) / deviation, taken from the moments themselves, the same box is an affine image
// whose circumscribed box has widths an LP resolves. Problem 1 over that larger box is still a
// lower bound for every distribution whose moments round to the given ones, and is feasible
// whenever one of them exists: phase 1 (continuous/moment_box.h, find_box_points) finds points
// carrying one, and the box problem's exchange certifies G on the whole interval.
#include <span>
#include <vector>

#include "continuous/moment_box.h"

namespace mb::lp {

// u = (z - mean) * inverse, both in long double.
struct LocalFrame {
  long double mean = 0, inverse = 1;
  double to_u(double z) const { return double((z - mean) * inverse); }
  double to_z(double u) const { return double(mean + u / inverse); }
};

// The frame of raw moments (E[z], E[z^2], ..): their mean and deviation, the deviation at least
// what the tolerances leave of the variance (a single atom's moments still have their rounding).
LocalFrame local_frame(std::span<const double> moments, std::span<const double> tolerance,
                       double zf);

// The box of E[u^k], k = 1..n, that contains the image of |E[z^j] - moments_j| <= tolerance_j:
// centres by the binomial expansion in long double, radii from the tolerances plus that
// expansion's rounding.
MomentBox local_moment_box(const LocalFrame& frame, std::span<const double> moments,
                           std::span<const double> tolerance);

struct LocalBoxAnswer {
  LocalFrame frame;
  MomentBox local;          // the box in u the answer is over (radii raised to the LP's resolution)
  ContinuousDomain domain;  // I in u, with the exchange's reach
  double zf_u = 0;          // z_f in u
  BoxPoints phase1;         // in u
  ContinuousBoxAnswer box;  // G's bracket (the same in z and in u)
  std::vector<double> support, weights;  // the finite optimum's distribution, in z
  bool ok() const { return phase1.found && box.ok(); }
};

// Problem 1 over the box, for the basis z, .., z^n (n = moments.size()) on [lo, hi].
LocalBoxAnswer solve_power_box_locally(double lo, double hi, std::span<const double> moments,
                                       std::span<const double> tolerance, double zf,
                                       const ContinuousSettings& settings = {});

// An upper end for G over the box of an answer (docs/reference.md §2, "The range over the rounding
// box"): the answer's G is the box's least, and the G of the kernel that was rounded lies anywhere
// up to the box's largest. G(b) is at most the mass at or in front of z_f of every distribution
// with moments b, so the largest such mass over the box, G+ = 1 - (the least mass strictly behind
// z_f), bounds G over the box from above. The least mass behind is the box problem in v = -u
// (odd moments and I reflected, z_f to -z_f), started from phase 1's points reflected; `upper`
// is 1 - its proven lower end, so it never lies below G of a distribution in the box.
// When GLPK finds no start for it (it can call such a box infeasible from every start, as it can
// the box of solve_power_box_locally), the upper end is 1, which holds too.
struct LocalBoxUpper {
  ContinuousBoxAnswer behind;  // the least mass strictly behind z_f over the box (in v)
  double upper = 1;            // 1 - behind.lower, or 1 when that box problem failed
  bool proven = false;         // behind.proven
};
LocalBoxUpper local_box_upper(const LocalBoxAnswer& answer,
                              const ContinuousSettings& settings = {});

}  // namespace mb::lp
