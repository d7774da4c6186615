// The certified optimum of a two-function basis's transform (docs/reference.md §8): for m = 2 the
// gain is a function of the two row angles alone, and a grid over both with a bound of
// each cell is an exhaustive search whose answer is an upper bound, not a guess.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "moments/quantization_transform.h"
#include "util/error.h"

namespace mb {

namespace {

// The largest |sin x| over x in [lo, hi]: 1 when the interval holds a peak (pi/2 + k pi), else
// the larger end's (|sin| rises towards each peak and falls away from it).
double largest_abs_sin(double lo, double hi) {
  const double k = std::ceil((lo - std::numbers::pi / 2) / std::numbers::pi);
  if (std::numbers::pi / 2 + k * std::numbers::pi <= hi) return 1;
  return std::max(std::abs(std::sin(lo)), std::abs(std::sin(hi)));
}

// The curve in whitened canonical coordinates y = W (A_can b + c_can) (see below) and what a row
// direction u(theta) = (cos theta, sin theta) of y needs.
struct Frame {
  const Basis& basis;
  Eigen::Matrix2d to_y;  // W A_can

  // A certified lower bound of the width w(theta') over |theta' - theta| <= half.
  double least_width(double theta, double half) const {
    const Eigen::Vector2d u(std::cos(theta), std::sin(theta)), normal(-u(1), u(0));
    const RowRange r = row_range(basis, (u.transpose() * to_y).transpose());
    // w(theta') >= u(theta') . v for the pair v = y(argmax) - y(argmin) of the centre (two points
    // of the curve), and u(theta') = cos(t) u + sin(t) normal with |t| <= half, u . v >= 0.
    const Eigen::Vector2d v = to_y * Eigen::Vector2d(basis[0](r.argmax) - basis[0](r.argmin),
                                                     basis[1](r.argmax) - basis[1](r.argmin));
    const double margin = 1e-12 * v.norm();
    return std::cos(half) * u.dot(v) - std::sin(half) * std::abs(normal.dot(v)) - margin;
  }
};

}  // namespace

double two_row_gain_bound_bits(const Basis& basis, int angles) {
  if (basis.size() != 2)
    throw InputError("the angle-grid bound is for two functions; the basis has " +
                     std::to_string(basis.size()));
  if (angles < 8) throw InputError("the angle-grid bound needs at least 8 angles");
  // In the canonical coordinates q = A_can b + c_can the curve lies in [0, 1]^2, and the gain over
  // the canonical storage is max log|det B| over the rows B of q's admissible transforms. Whiten
  // q's samples (any invertible W keeps the bound valid; this one makes the widths alike): rows u
  // of unit length in y = W q give B = diag(1 / w(u)) U W and
  //   gain = log|sin(theta_2 - theta_1)| - log w(theta_1) - log w(theta_2) + log|det W|.
  const QuantizationTransform canonical = quantization_transform(basis, "canonical");
  constexpr int kSamples = 1025;
  Eigen::MatrixXd q(kSamples, 2);
  for (int k = 0; k < kSamples; ++k) {
    const double z = double(k) / (kSamples - 1);
    q.row(k) = (canonical.A * Eigen::Vector2d(basis[0](z), basis[1](z)) + canonical.c).transpose();
  }
  const Eigen::MatrixXd centred = q.rowwise() - q.colwise().mean();
  const Eigen::Matrix2d W =
      whitening(centred.transpose() * centred / kSamples, "the angle-grid bound");
  const Frame frame{basis, W * canonical.A};
  const double step = std::numbers::pi / angles;
  // -log of the least width over each angle's cell [theta_k - step / 2, theta_k + step / 2].
  std::vector<double> minus_log_least(static_cast<size_t>(angles));
  for (int k = 0; k < angles; ++k) {
    const double least = frame.least_width(step * k, step / 2);
    if (!(least > 0))
      throw InputError("the angle-grid bound: " + std::to_string(angles) +
                       " angles are too few for this basis (a cell's width may vanish)");
    minus_log_least[size_t(k)] = -std::log(least);
  }
  // Rows are directions modulo pi, and |sin| has period pi: pairs (k, k + d mod angles) over
  // d in [0, angles) cover every pair of cells, their angles differing by d step +- step. The
  // bound's slack is first order in the step (the widths' and the sine's change across a cell).
  double best = -std::numeric_limits<double>::infinity();
  for (int d = 0; d < angles; ++d) {
    const double s = largest_abs_sin((d - 1) * step, (d + 1) * step);
    if (!(s > 0)) continue;
    double widths = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < angles; ++k)
      widths =
          std::max(widths, minus_log_least[size_t(k)] + minus_log_least[size_t((k + d) % angles)]);
    best = std::max(best, std::log(s) + widths);
  }
  // A rounding margin far above the sums' (a few hundred ulps of terms of order 1).
  return (best + std::log(std::abs(W.determinant()))) / std::numbers::ln2 + 1e-9;
}

}  // namespace mb
