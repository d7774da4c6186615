// The search for the transform of largest entropy gain (docs/reference.md §8): maximise
// F(A) = log|det A| - sum_i log w(a_i), w(a) = max_z a . b(z) - min_z a . b(z), over the rows a_i.
// F is invariant under scaling a row, and exp(-F) is the volume of the parallelepiped the rows'
// slabs cut around the hull of the curve b([0, 1]): the optimum is the smallest such one. The
// search runs on a dense grid of the curve with each extremum refined by cubic Hermite
// interpolation (values and derivatives), in whitened coordinates (the curve's covariance made the
// identity, so that the rows start well conditioned); the answer's rows are then fitted to their
// certified ranges (fit_rows), which is what the gain is measured with.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "moments/quantization_transform.h"
#include "util/error.h"

namespace mb {

namespace {

// The curve y(z) = W (b(z) - mean) on a grid, with dy/dz.
struct Curve {
  int n = 0, m = 0;
  double h = 0;
  Eigen::MatrixXd y, dy;  // n x m
  Eigen::RowVectorXd mean;
  Eigen::MatrixXd W;  // whitening, m x m
};

// The curve on n grid points, whitened by `frame`'s mean and W (its own when null), so that a
// matrix of rows means the same transform on every grid of one basis.
Curve sample_curve(const Basis& basis, int n, const Curve* frame = nullptr) {
  Curve c;
  c.n = n, c.m = int(basis.size()), c.h = 1.0 / (n - 1);
  Eigen::MatrixXd b(n, c.m), db(n, c.m);
  long double d[2];
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < c.m; ++j) {
      basis[j].derivatives((long double)(k) / (n - 1), 1, d);
      b(k, j) = double(d[0]), db(k, j) = double(d[1]);
    }
  if (frame) {
    c.mean = frame->mean, c.W = frame->W;
    c.y = (b.rowwise() - c.mean) * c.W.transpose();
    c.dy = db * c.W.transpose();
    return c;
  }
  c.mean = b.colwise().mean();
  const Eigen::MatrixXd centred = b.rowwise() - c.mean;
  const Eigen::MatrixXd covariance = centred.transpose() * centred / n;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(covariance);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  if (!(lambda(0) > 1e-300) || lambda(0) < 1e-26 * lambda(c.m - 1))
    throw InputError(
        "quantization transform: the basis's curve is degenerate on [0, 1] "
        "(covariance eigenvalue " +
        std::to_string(lambda(0)) + ")");
  c.W = eig.eigenvectors() * lambda.cwiseSqrt().cwiseInverse().asDiagonal() *
        eig.eigenvectors().transpose();
  c.y = centred * c.W.transpose();
  c.dy = db * c.W.transpose();
  return c;
}

// The extremum (max when sign = 1, min when -1) of a . y(z): the best grid point, then the cubic
// Hermite interpolant's extremum on the adjacent cell the derivative points to. Returns the value
// and sets `point` to y at the extremum (the value's gradient in a).
double extremum(const Curve& c, const Eigen::VectorXd& f, const Eigen::VectorXd& df, int k,
                double sign, Eigen::VectorXd& point) {
  point = c.y.row(k).transpose();
  double best = f(k);
  const double slope = sign * df(k);
  const int k0 = slope > 0 ? k : k - 1;
  if (slope == 0 || k0 < 0 || k0 + 1 >= c.n) return best;
  // Cubic on [k0, k0 + 1] in t in [0, 1]: p(t) with p(0), p(1), p'(0), p'(1) (scaled by h).
  const double p0 = f(k0), p1 = f(k0 + 1), m0 = c.h * df(k0), m1 = c.h * df(k0 + 1);
  // p'(t) = 3 a t^2 + 2 b t + m0 with a = 2 p0 - 2 p1 + m0 + m1, b = -3 p0 + 3 p1 - 2 m0 - m1.
  const double qa = 3 * (2 * p0 - 2 * p1 + m0 + m1), qb = 2 * (-3 * p0 + 3 * p1 - 2 * m0 - m1);
  double roots[2];
  int count = 0;
  if (std::abs(qa) < 1e-14 * (std::abs(qb) + std::abs(m0))) {
    if (qb != 0) roots[count++] = -m0 / qb;
  } else {
    const double disc = qb * qb - 4 * qa * m0;
    if (disc >= 0) {
      const double s = std::sqrt(disc), q = -0.5 * (qb + std::copysign(s, qb));
      if (q != 0) roots[count++] = q / qa, roots[count++] = m0 / q;
    }
  }
  for (int r = 0; r < count; ++r) {
    const double t = roots[r];
    if (!(t > 0 && t < 1)) continue;
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2,
                 h11 = t3 - t2;
    const double value = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
    if (sign * value > sign * best) {
      best = value;
      point = h00 * c.y.row(k0).transpose() + h10 * c.h * c.dy.row(k0).transpose() +
              h01 * c.y.row(k0 + 1).transpose() + h11 * c.h * c.dy.row(k0 + 1).transpose();
    }
  }
  return best;
}

// log w(a) and its gradient (y(z_max) - y(z_min)) / w.
double log_width(const Curve& c, const Eigen::VectorXd& a, Eigen::VectorXd* gradient) {
  const Eigen::VectorXd f = c.y * a, df = c.dy * a;
  Eigen::Index kmax, kmin;
  f.maxCoeff(&kmax);
  f.minCoeff(&kmin);
  Eigen::VectorXd top, bottom;
  const double hi = extremum(c, f, df, int(kmax), 1, top);
  const double lo = extremum(c, f, df, int(kmin), -1, bottom);
  const double w = hi - lo;
  if (!(w > 0)) return -std::numeric_limits<double>::infinity();
  if (gradient) *gradient = (top - bottom) / w;
  return std::log(w);
}

// F(A) (natural log) and its gradient; -inf for a singular A.
double objective(const Curve& c, const Eigen::MatrixXd& A, Eigen::MatrixXd* gradient) {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  const double det = lu.determinant();
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return -std::numeric_limits<double>::infinity();
  double value = std::log(std::abs(det));
  if (gradient) *gradient = lu.inverse().transpose();
  Eigen::VectorXd g;
  for (int i = 0; i < c.m; ++i) {
    const double lw = log_width(c, A.row(i).transpose(), gradient ? &g : nullptr);
    if (!std::isfinite(lw)) return -std::numeric_limits<double>::infinity();
    value -= lw;
    if (gradient) gradient->row(i) -= g.transpose();
  }
  return value;
}

// BFGS ascent with the weak Wolfe line search of Lewis and Overton (2013, "Nonsmooth optimization
// via quasi-Newton methods"), which stays sound where F is only piecewise smooth (an extremum of a
// row switching between two points of the curve). Rows are renormalised between restarts.
Eigen::MatrixXd ascend(const Curve& c, Eigen::MatrixXd A, int iterations) {
  const int m = c.m, dim = m * m;
  auto flat = [&](const Eigen::MatrixXd& M) {
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(M.data(), dim));
  };
  auto shaped = [&](const Eigen::VectorXd& v) {
    return Eigen::MatrixXd(Eigen::Map<const Eigen::MatrixXd>(v.data(), m, m));
  };
  for (int round = 0; round < 3; ++round) {
    A.rowwise().normalize();
    Eigen::MatrixXd G;
    double f = objective(c, A, &G);
    Eigen::VectorXd x = flat(A), g = -flat(G);  // minimise -F
    Eigen::MatrixXd H = Eigen::MatrixXd::Identity(dim, dim) * 0.1;
    bool progressed = false;
    for (int it = 0; it < iterations; ++it) {
      const Eigen::VectorXd d = -H * g;
      const double slope = g.dot(d);
      if (!(slope < 0)) break;
      double lo = 0, hi = std::numeric_limits<double>::infinity(), t = 1;
      Eigen::VectorXd x_new, g_new;
      double f_new = 0;
      bool accepted = false;
      for (int ls = 0; ls < 50; ++ls) {
        x_new = x + t * d;
        Eigen::MatrixXd Gn;
        f_new = objective(c, shaped(x_new), &Gn);
        g_new = -flat(Gn);
        if (!std::isfinite(f_new) || -f_new > -f + 1e-4 * t * slope) {
          hi = t;
        } else if (g_new.dot(d) < 0.9 * slope) {
          lo = t;
        } else {
          accepted = true;
          break;
        }
        t = std::isfinite(hi) ? (lo + hi) / 2 : 2 * lo;
      }
      if (!accepted) break;
      const Eigen::VectorXd s = x_new - x, y = g_new - g;
      const double sy = s.dot(y);
      const double gain = f_new - f;
      x = x_new, g = g_new, f = f_new;
      progressed = true;
      if (sy > 1e-300) {
        const double rho = 1 / sy;
        const Eigen::MatrixXd V = Eigen::MatrixXd::Identity(dim, dim) - rho * s * y.transpose();
        H = V * H * V.transpose() + rho * s * s.transpose();
      }
      if (gain < 1e-13 * std::max(1.0, std::abs(f))) break;
    }
    A = shaped(x);
    if (!progressed) break;
  }
  A.rowwise().normalize();
  return A;
}

// m = 2: F(theta_1, theta_2) = log|sin(theta_2 - theta_1)| - log w(theta_1) - log w(theta_2) over
// unit rows (cos theta, sin theta); every pair of angles on a grid of kAngles over [0, pi) (w is
// even in the row's sign), the best pair then refined by BFGS. Exhaustive: the grid covers the
// whole two-dimensional domain; two_row_gain_bound_bits bounds F over every cell between grid
// points (each cell's widths from below), which certifies how close the answer is to the optimum.
Eigen::MatrixXd exhaustive_two(const Curve& c) {
  constexpr int kAngles = 4096;
  std::vector<double> lw(kAngles);
  for (int i = 0; i < kAngles; ++i) {
    const double theta = std::numbers::pi * i / kAngles;
    lw[i] = log_width(c, Eigen::Vector2d(std::cos(theta), std::sin(theta)), nullptr);
  }
  double best = -std::numeric_limits<double>::infinity();
  int bi = 0, bj = 1;
  for (int i = 0; i < kAngles; ++i)
    for (int j = i + 1; j < kAngles; ++j) {
      const double f = std::log(std::sin(std::numbers::pi * (j - i) / kAngles)) - lw[i] - lw[j];
      if (f > best) best = f, bi = i, bj = j;
    }
  Eigen::MatrixXd A(2, 2);
  for (int r = 0; r < 2; ++r) {
    const double theta = std::numbers::pi * (r == 0 ? bi : bj) / kAngles;
    A(r, 0) = std::cos(theta), A(r, 1) = std::sin(theta);
  }
  return A;
}

Eigen::MatrixXd random_rotation(int m, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd M(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) M(i, j) = normal(rng);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(M);
  return qr.householderQ();
}

}  // namespace

OptimizedTransform optimize_transform(const Basis& basis) {
  check_quantizable(basis);
  const int m = int(basis.size());
  // The coarse grid ranks the starts; the fine one refines the best few.
  const Curve coarse = sample_curve(basis, 1025), fine = sample_curve(basis, 8193, &coarse);
  OptimizedTransform out;
  Eigen::MatrixXd best;
  if (m == 1) {
    best = Eigen::MatrixXd::Identity(1, 1);  // one row: every direction is the same transform
    out.exhaustive = true;
  } else if (m == 2) {
    best = ascend(fine, exhaustive_two(coarse), 200);
    out.exhaustive = true;
    out.starts = 1;
  } else {
    // Starts per dimension: 16 reach the best known optimum for m <= 4 (seed 000's theta_4) in
    // well under a second; m = 5, 6 need 64 (fewer stop 1e-3 bits short for m = 6).
    const int starts = (m <= 4 ? 16 : 64) * m, iterations = 60 * m, kept = 3;
    std::mt19937_64 rng(0x51ed0061);
    std::vector<std::pair<double, Eigen::MatrixXd>> found;
    // The whitened axes, the canonical rows (each function alone) and random rotations.
    std::vector<Eigen::MatrixXd> initial = {Eigen::MatrixXd::Identity(m, m), coarse.W.inverse()};
    while (int(initial.size()) < starts) initial.push_back(random_rotation(m, rng));
    for (const Eigen::MatrixXd& start : initial) {
      const Eigen::MatrixXd A = ascend(coarse, start, iterations);
      found.emplace_back(objective(coarse, A, nullptr), A);
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    double best_value = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::min(kept, int(found.size())); ++i) {
      const Eigen::MatrixXd A = ascend(fine, found[i].second, 4 * iterations);
      const double value = objective(fine, A, nullptr);
      if (value > best_value) best_value = value, best = A;
    }
    out.starts = starts;
  }
  // Rows in the basis's own coordinates: a . W (b - mean); the mean goes into c by fitting.
  const Eigen::MatrixXd directions = best * fine.W;
  out.transform = fit_rows(basis, directions);
  out.gain_bits = entropy_gain_bits(basis, out.transform);
  return out;
}

}  // namespace mb
