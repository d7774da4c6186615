// Upper bounds of the entropy gain from hull volumes (docs/reference.md §8), with Qhull's
// reentrant library computing the convex hulls of sampled points.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "moments/quantization_transform.h"
#include "util/error.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace mb {

namespace {

// Qhull's volume of `points`; where its precision fails (a nearly flat hull), of the joggled
// points, bounded from below as sampled_hull_volume says.
double convex_hull_volume(const std::vector<double>& points, int dim) {
  try {
    return sampled_hull_volume(points, dim, false);
  } catch (const InputError&) {
    return sampled_hull_volume(points, dim, true);
  }
}

// Samples of the curve and of its difference body: Chebyshev-spaced depths, denser where the
// moment curves bend most (near 0 and 1). The counts keep Qhull's facets (about n^(m/2) for the
// neighbourly power-moment curves) to a few hundred thousand.
int curve_samples(int m) {
  static const int kCounts[] = {0, 2, 4096, 1500, 300, 120, 64, 40, 28};
  return m < int(std::size(kCounts)) ? kCounts[m] : 24;
}
// At least m + 2 points: the differences of n points span only n - 1 dimensions.
int difference_samples(int m) {
  static const int kCounts[] = {0, 2, 512, 200, 60, 28, 22, 12, 10};
  return m < int(std::size(kCounts)) ? kCounts[m] : m + 2;
}

std::vector<double> depths(int n) {
  std::vector<double> z(n);
  for (int k = 0; k < n; ++k) z[k] = 0.5 - 0.5 * std::cos(std::numbers::pi * k / (n - 1));
  return z;
}

}  // namespace

double sampled_hull_volume(std::vector<double> points, int dim, bool joggle) {
  const int n = int(points.size()) / dim;
  qhT context;
  qhT* qh = &context;
  // Qhull's messages go to a scratch file, quoted in the error below; without one (no writable
  // temporary directory) they go to stderr and the error says so.
  FILE* errors = std::tmpfile();
  qh_zero(qh, errors ? errors : stderr);
  char plain[] = "qhull Qt", joggled[] = "qhull QJ";
  const int exit = qh_new_qhull(qh, dim, n, points.data(), False, joggle ? joggled : plain, nullptr,
                                errors ? errors : stderr);
  double volume = 0;
  if (exit == 0) {
    qh_getarea(qh, qh->facet_list);
    volume = qh->totvol;
    if (joggle) volume -= 2 * std::sqrt(double(dim)) * qh->JOGGLEmax * qh->totarea;
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0, total_long = 0;
  qh_memfreeshort(qh, &still_long, &total_long);
  std::string message = errors ? "" : "(Qhull's messages are on stderr)";
  if (errors) {
    std::rewind(errors);
    char line[256];
    while (message.size() < 400 && std::fgets(line, sizeof line, errors)) message += line;
    std::fclose(errors);
  }
  if (exit != 0 || !(volume > 0))
    throw InputError("hull volume: Qhull failed on " + std::to_string(n) +
                     " points of the curve in " + std::to_string(dim) +
                     " dimensions (a degenerate basis?): " + message);
  return volume;
}

Eigen::MatrixXd whitening(const Eigen::MatrixXd& covariance, const std::string& what) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(covariance);
  if (!(eig.eigenvalues()(0) > 0))
    throw InputError(what + ": the basis's curve is degenerate on [0, 1]");
  return eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().cwiseInverse().asDiagonal() *
         eig.eigenvectors().transpose();
}

double GainBounds::best_bits() const {
  return std::min({hull_bound_bits, difference_bound_bits, angle_grid_bits});
}

GainBounds gain_bounds(const Basis& basis) {
  const int m = int(basis.size());
  const QuantizationTransform canonical = quantization_transform(basis, "canonical");
  const double canonical_det = std::abs(canonical.A.determinant());
  auto stored = [&](const std::vector<double>& z) {
    std::vector<Eigen::VectorXd> q;
    Eigen::VectorXd b(m);
    for (double x : z) {
      for (int j = 0; j < m; ++j) b(j) = basis[j](x);
      q.push_back(canonical.A * b + canonical.c);
    }
    return q;
  };
  GainBounds out;
  if (m == 1) {
    out.hull_volume = 1 / canonical_det, out.difference_volume = 2 / canonical_det;
    return out;
  }
  // Hulls are taken in coordinates where the curve's samples have identity covariance (a curve of
  // nearly dependent functions, e.g. z^3 ... z^6, is otherwise too thin for Qhull's arithmetic);
  // volumes come back through |det W|.
  const std::vector<Eigen::VectorXd> curve = stored(depths(curve_samples(m)));
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(m);
  for (const auto& q : curve) mean += q / double(curve.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(m, m);
  for (const auto& q : curve)
    covariance += (q - mean) * (q - mean).transpose() / double(curve.size());
  const Eigen::MatrixXd W = whitening(covariance, "hull volume");
  const double det_W = std::abs(W.determinant());
  std::vector<double> points;
  for (const auto& q : curve) {
    const Eigen::VectorXd y = W * (q - mean);
    points.insert(points.end(), y.data(), y.data() + m);
  }
  const double hull = convex_hull_volume(points, m) / det_W;
  // The difference body in the same whitened coordinates: W (q_i - q_k) = y_i - y_k.
  const std::vector<Eigen::VectorXd> sparse = stored(depths(difference_samples(m)));
  points.clear();
  for (size_t i = 0; i < sparse.size(); ++i)
    for (size_t k = 0; k < sparse.size(); ++k) {
      if (i == k) continue;  // 0, inside D: n copies of it trouble Qhull
      const Eigen::VectorXd d = W * (sparse[i] - sparse[k]);
      points.insert(points.end(), d.data(), d.data() + m);
    }
  const double difference = convex_hull_volume(points, m) / det_W;
  out.hull_volume = hull / canonical_det;
  out.difference_volume = difference / canonical_det;
  out.hull_bound_bits = -std::log2(hull);
  out.difference_bound_bits = m - std::log2(difference);
  if (m == 2) out.angle_grid_bits = two_row_gain_bound_bits(basis, kAngleGridAngles);
  return out;
}

}  // namespace mb
