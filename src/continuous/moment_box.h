#pragma once
// Problem 1 with moments known only to a tolerance (docs/reference.md §2, "Moments with a
// tolerance"): minimise the mass in front of z_f over all distributions on I whose stored values
// lie in the box |E[s_i] - c_i| <= eps_i, where s = offset + transform * b(z) is what a moment map
// stores (the moments themselves, or the 16-bit map's theta_4 coordinates, docs/reference.md §4). A
// boundary moment vector (few atoms) rounded to double may lie just outside the moment cone, where
// the exact LP is infeasible; the box problem is feasible whenever the true moments are within eps,
// and its G is a lower bound for every distribution that could have produced the stored values.
// Solved by GLPK on the raw rows, each scaled by its largest value over the points (our simplex has
// no bounded rows); on the continuous interval by the exchange method of continuous/continuous.h,
// whose certificate serves unchanged: the box LP's dual is again a function phi <= step on I.
#include <span>
#include <vector>

#include "continuous/continuous.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "util/eigen.h"

namespace mb::lp {

struct MomentBox {
  std::vector<double> center, tolerance;  // c_i and eps_i, one per stored value
  Eigen::MatrixXd transform;              // s = offset + transform * b; empty: s = b
  Eigen::VectorXd offset;
  // The box of the moments themselves.
  static MomentBox of_moments(std::vector<double> moments, std::vector<double> tolerance) {
    return {std::move(moments), std::move(tolerance), {}, {}};
  }
};

struct MomentBoxAnswer {
  ProblemStatus status = ProblemStatus::Unstable;
  double G = 0;
  std::vector<double> support, weights;  // the optimal distribution (points, weights)
  // Infeasible: the smallest t such that a distribution on the points has
  // |E[s_i] - c_i| <= t max(|c_i|, eps_i) for every i, i.e. how far outside the cone c lies,
  // relative to each value (0 when feasible).
  double relative_distance = 0;
};

// On the given points of I; `behind`: the least mass strictly behind z_f instead (Problem::behind),
// so that 1 minus it bounds G over the box from above.
MomentBoxAnswer solve_moment_box(const Basis& basis, const MomentBox& box, double zf,
                                 std::span<const double> points, bool behind = false);
// `problem` from factory.from_moments (its points and untransformed moments are the box's centre;
// its `behind` chooses the objective).
MomentBoxAnswer solve_moment_box(const ProblemFactory& factory, const Problem& problem,
                                 std::span<const double> tolerance);

// eps_j = ulps * ulp(|b_j|), at least ulps * ulp of b_j's largest value on the points (a zero
// moment still has the rounding of the sums that made it).
std::vector<double> ulp_box(const ProblemFactory& factory, const Problem& problem, double ulps);

struct ContinuousBoxAnswer {
  MomentBoxAnswer finite;  // the last round's LP on its points (an upper bound)
  double upper = 0, lower = 0;
  double violation = 0;
  bool proven = false;  // as ContinuousSolution::proven
  int rounds = 0, points_added = 0;
  bool stalled = false;  // a later round's LP failed: the bracket is the last round's
  bool ok() const { return finite.status == ProblemStatus::Optimal; }
  double width() const { return upper - lower; }
};

// Phase 1 of the box problem on the continuous domain: points of it that carry a distribution in
// the box. The exchange method on the elastic LP (minimise t with
// |E[s_i] - c_i| <= eps_i + t scale_i), adding points where its dual function rises above 0.
struct BoxPoints {
  bool found = false;
  std::vector<double> points;  // found: the support of a distribution in the box
  double distance = 0;         // the last t (NaN: GLPK gave up); 0 when found
  int rounds = 0;
};
BoxPoints find_box_points(const Basis& basis, const MomentBox& box, const ContinuousDomain& domain,
                          std::span<const double> seed_points,
                          const ContinuousSettings& settings = {});

// The box problem on the continuous domain, starting from `seed_points` (points of I that admit
// a distribution in the box, e.g. the atoms of the one that was stored: the exchange has no
// phase 1; z_f and the interval's ends join them). The bracket [lower, upper] holds the box
// problem's G; lower is proven when `proven` (weak duality over every distribution on I in the
// box).
ContinuousBoxAnswer solve_moment_box_continuous(const Basis& basis, const MomentBox& box, double zf,
                                                const ContinuousDomain& domain,
                                                std::span<const double> seed_points,
                                                const ContinuousSettings& settings = {});

}  // namespace mb::lp
