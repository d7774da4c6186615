#include "lp/problem.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace mb::lp {

int Problem::index_of(double z) const {
  auto it = std::lower_bound(points.begin(), points.end(), z);
  return it != points.end() && *it == z ? int(it - points.begin()) : -1;
}

std::vector<double> grid_points(const Discretization& disc) {
  if (disc.grid < 2) throw InputError("grid: at least 2 points are needed, got " + std::to_string(disc.grid));
  if (!(disc.lo < disc.hi)) throw InputError("interval: expected lo < hi");
  std::vector<double> g(disc.grid);
  for (int i = 0; i < disc.grid; ++i) g[i] = disc.lo + (disc.hi - disc.lo) * i / (disc.grid - 1);
  g.back() = disc.hi;
  return g;
}

double quantize_to_grid(const Discretization& disc, double z) {
  double step = (disc.hi - disc.lo) / (disc.grid - 1);
  double k = std::clamp(std::round((z - disc.lo) / step), 0.0, double(disc.grid - 1));
  return k == disc.grid - 1 ? disc.hi : disc.lo + (disc.hi - disc.lo) * k / (disc.grid - 1);
}

namespace {

std::vector<double> point_set(const Discretization& disc, std::span<const double> extra, double zf) {
  std::vector<double> points = grid_points(disc);
  for (double z : extra) {
    if (!std::isfinite(z)) throw InputError("points: a depth is not finite");
    points.push_back(disc.quantize ? quantize_to_grid(disc, z) : z);
  }
  if (!std::isfinite(zf)) throw InputError("zf: not finite");
  // z_f joins I only where it is admissible; outside [lo, hi] it changes nothing but the cost.
  if (zf >= disc.lo && zf <= disc.hi) points.push_back(zf);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

// Evaluates (1, b(z_i)) and orthonormalises the rows: A^T = Q R, rows := R^{-T} A = Q^T.
// Returns R^{-T} applied through `transform` for right-hand sides.
struct RowTransform {
  Eigen::MatrixXd r_upper;  // (m+1) x (m+1)
  Eigen::VectorXd apply(const Eigen::VectorXd& v) const {
    return r_upper.transpose().triangularView<Eigen::Lower>().solve(v);
  }
};

RowTransform fill_rows(const Basis& basis, Problem& p) {
  const int n = int(p.points.size()), k = int(basis.size()) + 1;
  Eigen::MatrixXd at(n, k);
  at.col(0).setOnes();
  std::vector<double> values(n);
  for (int j = 0; j + 1 < k; ++j) {
    basis[j].evaluate(p.points, values);
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(values[i]))
        throw InputError("basis function '" + basis[j].name() + "' is not finite at z = " + std::to_string(p.points[i]));
      at(i, j + 1) = values[i];
    }
  }
  if (n < k) throw InputError("the depth set has fewer points than the basis has functions plus one");
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(at);
  RowTransform t;
  t.r_upper = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
  double largest = t.r_upper.diagonal().cwiseAbs().maxCoeff();
  for (int r = 0; r < k; ++r)
    if (std::abs(t.r_upper(r, r)) < 1e-12 * largest)
      throw InputError("basis {" + [&] {
        std::string s;
        for (const auto& name : basis.names()) s += (s.empty() ? "" : ", ") + name;
        return s;
      }() + "} is linearly dependent together with the constant on the depth set");
  // Q^T = R^{-T} A^T^T: solve R^T X = A for X (k x n).
  Eigen::MatrixXd rows = t.r_upper.transpose().triangularView<Eigen::Lower>().solve(at.transpose());
  p.rows = k;
  p.cols = n;
  p.matrix.resize(size_t(k) * n);
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < n; ++i) p.matrix[size_t(r) * n + i] = rows(r, i);
  p.cost.resize(n);
  for (int i = 0; i < n; ++i) p.cost[i] = p.points[i] < p.zf;
  return t;
}

}  // namespace

Problem make_problem(const Basis& basis, const Discretization& disc, std::span<const double> moments, double zf,
                     std::span<const double> extra_points) {
  if (moments.size() != basis.size())
    throw InputError("moments: expected " + std::to_string(basis.size()) + " values (one per basis function), got " +
                     std::to_string(moments.size()));
  Problem p;
  p.zf = zf;
  p.points = point_set(disc, extra_points, zf);
  RowTransform t = fill_rows(basis, p);
  Eigen::VectorXd b(p.rows);
  b(0) = 1;
  for (size_t j = 0; j < moments.size(); ++j) {
    if (!std::isfinite(moments[j])) throw InputError("moments: value " + std::to_string(j + 1) + " is not finite");
    b(j + 1) = moments[j];
  }
  Eigen::VectorXd r = t.apply(b);
  p.rhs.assign(r.data(), r.data() + r.size());
  p.moments.assign(moments.begin(), moments.end());
  return p;
}

Problem make_problem_from_distribution(const Basis& basis, const Discretization& disc, std::span<const double> depths,
                                       std::span<const double> weights, double zf) {
  if (depths.size() != weights.size() || depths.empty())
    throw InputError("distribution: expected as many weights as depths, at least one");
  Problem p;
  p.zf = zf;
  p.points = point_set(disc, depths, zf);
  fill_rows(basis, p);
  // rhs = rows * w for the distribution itself, accumulated in a fixed order.
  p.rhs.assign(p.rows, 0.0);
  p.moments.assign(basis.size(), 0.0);
  double total = 0;
  for (size_t d = 0; d < depths.size(); ++d) total += weights[d];
  for (size_t d = 0; d < depths.size(); ++d) {
    double z = disc.quantize ? quantize_to_grid(disc, depths[d]) : depths[d];
    int i = p.index_of(z);
    double w = weights[d] / total;
    for (int r = 0; r < p.rows; ++r) p.rhs[r] += w * p.at(r, i);
    auto known = std::find(p.start_support.begin(), p.start_support.end(), i);
    if (known == p.start_support.end()) {
      p.start_support.push_back(i);
      p.start_weights.push_back(w);
    } else {
      p.start_weights[known - p.start_support.begin()] += w;  // quantized depths may coincide
    }
    for (size_t j = 0; j < basis.size(); ++j) p.moments[j] += w * basis[j](z);
  }
  return p;
}

}  // namespace mb::lp
