#include "moments/quantization_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "moments/storage.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

constexpr long double kLongEps = std::numeric_limits<long double>::epsilon();
constexpr double kDoubleEps = std::numeric_limits<double>::epsilon();

void require_derivatives(const Basis& basis) {
  for (size_t j = 0; j < basis.size(); ++j)
    if (!basis[j].has_derivatives())
      throw InputError("basis function '" + basis[j].name() +
                       "': a quantization transform needs the exact range of every row over [0, "
                       "1], proven from closed-form derivatives, and an expression has none; use "
                       "catalog functions (docs/reference.md §5, §8)");
}

// f(z) = a . b(z) with its first `order` derivatives, and the sum of its terms' magnitudes (the
// rounding allowance's scale).
struct RowValue {
  long double d[3] = {0, 0, 0};
  long double magnitude = 0;
};

RowValue row_value(const Basis& basis, const Eigen::VectorXd& a, long double z, int order) {
  RowValue v;
  long double derivatives[3];
  for (size_t j = 0; j < basis.size(); ++j) {
    if (a(j) == 0) continue;
    basis[j].derivatives(z, order, derivatives);
    for (int k = 0; k <= order; ++k) v.d[k] += a(j) * derivatives[k];
    v.magnitude += std::abs(a(j) * derivatives[0]);
  }
  return v;
}

struct Maximum {
  long double value, at, upper;
};

// The maximum of f = a . b over [0, 1] by branch and bound: a cell [l, u] with midpoint x and
// radius r is bounded by the Taylor model f(x) + |f'(x)| r + max|f''| r^2 / 2 (max|f''| from the
// functions' proven derivative bounds) plus the rounding allowance, discarded when that is within
// `tolerance` of the best value seen, bisected otherwise. The best value is polished by Newton's
// method on f' from the best sample, so the bound closes in on an attained value.
Maximum certified_maximum(const Basis& basis, const Eigen::VectorXd& a) {
  constexpr int kCells = 64;
  constexpr int kMaxDepth = 48;
  constexpr int kMaxCells = 200000;  // beyond, every cell left is bounded as it is (still valid)
  long double best = -std::numeric_limits<long double>::infinity(), best_at = 0, scale = 0;
  long double lowest = std::numeric_limits<long double>::infinity();
  auto consider = [&](long double z) {
    const RowValue v = row_value(basis, a, z, 0);
    scale = std::max(scale, v.magnitude);
    lowest = std::min(lowest, v.d[0]);
    if (v.d[0] > best) best = v.d[0], best_at = z;
  };
  for (int i = 0; i <= 4 * kCells; ++i) consider((long double)(i) / (4 * kCells));
  // Newton on f' from the best sample: a maximum inside [0, 1] is a root of f' with f'' < 0.
  for (long double z = best_at, step = 0; step < 40; ++step) {
    const RowValue v = row_value(basis, a, z, 2);
    if (v.d[2] >= 0) break;
    const long double next = std::clamp(z - v.d[1] / v.d[2], 0.0L, 1.0L);
    if (next == z) break;
    z = next;
    consider(z);
  }
  const long double spread = std::max(best - lowest, scale * 1e-12L);
  const long double rounding = 64 * kLongEps;
  // No bisection removes the rounding allowance: a tolerance below it would split the cells around
  // the maximum down to kMaxDepth.
  const long double tolerance = std::max(1e-12L * spread, 4 * rounding * scale);
  long double upper = best;
  struct Cell {
    long double lo, hi;
    int depth;
  };
  std::vector<Cell> cells;
  for (int i = 0; i < kCells; ++i)
    cells.push_back({(long double)(i) / kCells, (long double)(i + 1) / kCells, 0});
  for (int visited = 0; !cells.empty(); ++visited) {
    const Cell cell = cells.back();
    cells.pop_back();
    const long double x = (cell.lo + cell.hi) / 2, r = (cell.hi - cell.lo) / 2;
    const RowValue v = row_value(basis, a, x, 1);
    if (v.d[0] > best) best = v.d[0], best_at = x;
    long double curvature = 0;
    for (size_t j = 0; j < basis.size(); ++j)
      if (a(j) != 0)
        curvature += std::abs((long double)a(j)) * basis[j].derivative_bound(2, cell.lo, cell.hi);
    const long double bound =
        v.d[0] + std::abs(v.d[1]) * r + curvature * r * r / 2 + rounding * (v.magnitude + scale);
    if (!std::isfinite(bound))
      throw InputError("basis: a row's range is unbounded near z = " + round_trip(double(x)));
    if (bound <= best + tolerance || cell.depth >= kMaxDepth || visited >= kMaxCells) {
      upper = std::max(upper, bound);
      continue;
    }
    cells.push_back({cell.lo, x, cell.depth + 1});
    cells.push_back({x, cell.hi, cell.depth + 1});
  }
  return {best, best_at, std::max(upper, best)};
}

// sum_j |a_j| max_z |b_j(z)|, proven from above: the scale of a row's terms.
double largest_magnitude_bound(const Basis& basis, const Eigen::VectorXd& a,
                               const std::vector<double>& function_magnitudes) {
  double s = 0;
  for (size_t j = 0; j < basis.size(); ++j) s += std::abs(a(j)) * function_magnitudes[j];
  return s;
}

std::vector<double> function_magnitudes(const Basis& basis) {
  std::vector<double> out(basis.size());
  for (size_t j = 0; j < basis.size(); ++j) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(Eigen::Index(basis.size()));
    e(j) = 1;
    out[j] = double(std::max(std::abs(certified_maximum(basis, e).upper),
                             std::abs(certified_maximum(basis, -e).upper)));
  }
  return out;
}

}  // namespace

void check_quantizable(const Basis& basis) {
  if (basis.size() == 0) throw InputError("basis: no functions given");
  basis.check_independent(0, 1);  // first: a constant is degenerate whatever its form
  require_derivatives(basis);
}

RowRange row_range(const Basis& basis, const Eigen::VectorXd& a) {
  require_derivatives(basis);
  const Maximum hi = certified_maximum(basis, a), lo = certified_maximum(basis, -a);
  RowRange r;
  r.max = double(hi.value), r.argmax = double(hi.at), r.max_upper = double(hi.upper);
  r.min = double(-lo.value), r.argmin = double(lo.at), r.min_lower = double(-lo.upper);
  // Conversions to double round to nearest: push the bounds outwards by their ulp.
  r.max_upper = std::nextafter(r.max_upper, std::numeric_limits<double>::infinity());
  r.min_lower = std::nextafter(r.min_lower, -std::numeric_limits<double>::infinity());
  return r;
}

QuantizationTransform fit_rows(const Basis& basis, const Eigen::MatrixXd& directions) {
  const Eigen::Index m = Eigen::Index(basis.size());
  if (directions.rows() != m || directions.cols() != m)
    throw InputError("quantization transform: " + std::to_string(directions.rows()) + "x" +
                     std::to_string(directions.cols()) + " rows for a basis of " +
                     std::to_string(m) + " functions");
  QuantizationTransform t{Eigen::MatrixXd(m, m), Eigen::VectorXd(m)};
  const std::vector<double> magnitudes = function_magnitudes(basis);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::VectorXd a = directions.row(i).transpose();
    const RowRange r = row_range(basis, a);
    // A and c are rounded to double, and q = A b + c evaluated in double: widen the range by a
    // few ulps of the row's largest term so that rounding cannot carry q outside [0, 1].
    const double magnitude = largest_magnitude_bound(basis, a, magnitudes);
    const double margin = 8 * kDoubleEps * magnitude;
    const double lo = r.min_lower - margin, width = r.max_upper + margin - lo;
    if (!std::isfinite(width) || !(width > 1e-9 * magnitude))
      throw InputError("quantization transform: row " + std::to_string(i) +
                       " is constant on [0, 1] (range " + round_trip(width) +
                       "); the basis or the rows are degenerate");
    t.A.row(i) = directions.row(i) / width;
    t.c(i) = -lo / width;
  }
  const double det = t.A.determinant();
  if (!std::isfinite(det) || det == 0 || std::abs(t.A.fullPivLu().rcond()) < 1e-14)
    throw InputError("quantization transform: the rows are linearly dependent (det " +
                     round_trip(det) + ")");
  return t;
}

namespace {

bool is_power_basis(const Basis& basis) {
  for (size_t j = 0; j < basis.size(); ++j) {
    const std::string expected = j == 0 ? "z" : "z^" + std::to_string(j + 1);
    if (basis[j].name() != expected) return false;
  }
  return true;
}

QuantizationTransform canonical_transform(const Basis& basis) {
  return fit_rows(
      basis, Eigen::MatrixXd::Identity(Eigen::Index(basis.size()), Eigen::Index(basis.size())));
}

}  // namespace

QuantizationTransform quantization_transform(const Basis& basis, const std::string& kind) {
  if (kind != "canonical" && kind != "seed" && kind != "optimized")
    throw InputError("transform: '" + kind + "' is unknown; expected canonical, seed or optimized");
  check_quantizable(basis);
  if (kind == "canonical") return canonical_transform(basis);
  if (kind == "seed") {
    // Seed 000 §4.3 prints theta_2 and theta_4 only (moments/storage.h holds them).
    const size_t m = basis.size();
    if (!is_power_basis(basis) || (m != 2 && m != 4))
      throw InputError(
          "transform: 'seed' exists for the power bases (z, z^2) and (z, z^2, z^3, "
          "z^4) only (seed 000 §4.3 prints theta_2 and theta_4); the basis has " +
          std::to_string(m) + " functions" +
          (is_power_basis(basis) ? "" : " and is not a power basis"));
    const MomentStorage seed = m == 2 ? unorm16_power2_storage() : unorm16_power4_storage();
    return fit_rows(basis, seed.transform);
  }
  return optimize_transform(basis).transform;
}

double entropy_gain_bits(const Basis& basis, const QuantizationTransform& t) {
  const QuantizationTransform canonical = canonical_transform(basis);
  return std::log2(std::abs(t.A.determinant())) - std::log2(std::abs(canonical.A.determinant()));
}

double admissibility_violation(const Basis& basis, const QuantizationTransform& t) {
  double worst = -std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < t.A.rows(); ++i) {
    const RowRange r = row_range(basis, t.A.row(i).transpose());
    worst = std::max({worst, r.max_upper + t.c(i) - 1, -(r.min_lower + t.c(i))});
  }
  return worst;
}

}  // namespace mb
