#pragma once
// Affine transforms that spread a basis's moment vectors over [0, 1]^m before they are quantized
// (docs/reference.md §8; seed 000 §4.3, seed 004 §2.5). theta(b) = A b + c is admissible when
// theta(b(z)) lies in [0, 1]^m for every z in [0, 1]; an affine map raises the differential entropy
// of the stored vectors by log2 |det A| (seed 000, Proposition 6), so the best transform maximises
// log2 |det A| - sum_i log2 (max_z a_i . b(z) - min_z a_i . b(z)) over row directions a_i, each row
// then scaled and shifted onto its exact range. Ranges are certified enclosures from the catalog
// functions' closed-form derivatives; an expression without them is refused (InputError), since
// sampling understates a range and a transform fitted to samples can leave [0, 1]^m.
#include <limits>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "util/eigen.h"

namespace mb {

struct QuantizationTransform {
  Eigen::MatrixXd A;  // q = A b + c in [0, 1]^m for every b = b(z), z in [0, 1]
  Eigen::VectorXd c;
};

// The extrema of f(z) = a . b(z) over z in [0, 1]: attained values (at argmin, argmax) and proven
// bounds, min_lower <= min_z f <= min and max <= max_z f <= max_upper.
struct RowRange {
  double min = 0, max = 0;
  double argmin = 0, argmax = 0;
  double min_lower = 0, max_upper = 0;
  double width() const { return max_upper - min_lower; }  // certified from above
};

// InputError when a function of `basis` has no closed-form derivatives (an expression), or when
// the basis is degenerate on [0, 1] (Basis::check_independent: a constant, dependent functions).
void check_quantizable(const Basis& basis);

// InputError when a function of `basis` has no closed-form derivatives (an expression).
RowRange row_range(const Basis& basis, const Eigen::VectorXd& a);

// Rows of `directions` scaled and shifted so that each certified range maps onto [0, 1].
// InputError when `directions` is singular or a row is constant on [0, 1].
QuantizationTransform fit_rows(const Basis& basis, const Eigen::MatrixXd& directions);

// kind: "canonical" (each function scaled by its own range: the identity for power moments),
// "seed" (seed 000's theta_2 / theta_4 for (z, z^2) / (z, ..., z^4), rows fitted to their exact
// ranges; InputError for any other basis), "optimized" (optimize_transform). InputError on an
// unknown kind, a degenerate basis (check_independent on [0, 1]) or an expression.
QuantizationTransform quantization_transform(const Basis& basis, const std::string& kind);

// log2 |det A| - log2 |det A_canonical|: the bits of differential entropy `t` gains over the
// canonical transform (seed 000, Proposition 6).
double entropy_gain_bits(const Basis& basis, const QuantizationTransform& t);

// The largest excursion of A b(z) + c outside [0, 1] over z in [0, 1], from the certified ranges
// (<= 0 for an admissible transform; fit_rows's are slightly below 0, its ranges widened by a
// rounding margin).
double admissibility_violation(const Basis& basis, const QuantizationTransform& t);

// The search's answer: the best transform found, its gain and how it was searched (gain_bounds
// gives the certified upper bounds to set beside the gain).
struct OptimizedTransform {
  QuantizationTransform transform;
  double gain_bits = 0;     // entropy_gain_bits(transform)
  int starts = 0;           // multistart count (m = 2: the exhaustive angle grid, 1)
  bool exhaustive = false;  // m = 1; m = 2: every pair of row directions on a grid, refined
};
// check_quantizable first. Deterministic (fixed seeds): m = 2 searches both row angles
// exhaustively; larger m runs a multistart BFGS ascent from whitened random rotations.
OptimizedTransform optimize_transform(const Basis& basis);

// theta_6: the search's answer for the power basis (z, ..., z^6), written out
// (moments/power6_transform.cpp): 30.587 bits over the canonical storage; admissible.
QuantizationTransform power6_optimized_transform();

// Upper bounds of the gain (docs/reference.md §8). The transformed hull of b([0, 1]) fits in the
// unit cube, so |det A| vol(H) <= 1; every row maps the difference body D = H - H into [-1, 1], so
// |det A| vol(D) <= 2^m (tighter: vol(D) >= 2^m vol(H) by Brunn-Minkowski). Volumes are those of
// convex hulls of samples (Qhull), lower bounds of the true ones, so the bounds stay valid.
// The angles of each row that gain_bounds' two-function bound grids [0, pi) into.
constexpr int kAngleGridAngles = 4096;
struct GainBounds {
  double hull_volume = 0;            // vol of hull(b(z_k)), a lower bound of vol(H)
  double difference_volume = 0;      // vol of hull(b(z_k) - b(z_l)), a lower bound of vol(D)
  double hull_bound_bits = 0;        // -log2(|det A_canonical| vol(H))
  double difference_bound_bits = 0;  // -log2(|det A_canonical| vol(D) / 2^m)
  // m = 2: two_row_gain_bound_bits over kAngleGridAngles; infinite (no bound) for other m.
  double angle_grid_bits = std::numeric_limits<double>::infinity();
  double best_bits() const;  // the smallest of them
};
GainBounds gain_bounds(const Basis& basis);

// m = 2: the largest gain of any admissible transform, bounded from above over a grid of
// `angles` row directions on [0, pi) for each row, every cell's width bounded from below by the
// attained extrema of its centre (moments/angle_grid_bound.cpp): an exhaustive search of both row
// angles, certified; its slack is first order in pi / angles. InputError for other m, or when
// `angles` is too coarse for the basis.
double two_row_gain_bound_bits(const Basis& basis, int angles);

// W = V diag(lambda)^(-1/2) V^T for a covariance V diag(lambda) V^T: the coordinates in which a
// curve's samples have identity covariance, where the bounds take their hulls and angles.
// InputError "`what`: the basis's curve is degenerate on [0, 1]" when an eigenvalue is not > 0.
Eigen::MatrixXd whitening(const Eigen::MatrixXd& covariance, const std::string& what);

// The volume of the convex hull of `points` (n x dim, row-major) from Qhull, triangulated ("Qt")
// so that it is the facets' simplices summed. With `joggle` ("QJ", Qhull's remedy for its
// precision errors, the fallback gain_bounds takes) every point moves by at most JOGGLEmax a
// coordinate, so the joggled hull lies within eps = sqrt(dim) JOGGLEmax of the sampled one and
// exceeds it by at most about eps times its surface: twice that is subtracted, and the result
// stays below the sampled hull's volume. InputError when Qhull fails.
double sampled_hull_volume(std::vector<double> points, int dim, bool joggle);

}  // namespace mb
