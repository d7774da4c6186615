#include "lp/problem.h"

#include <algorithm>
#include <cmath>

#include "lp/row_count.h"
#include "util/eigen.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb::lp {

namespace {

// The largest |value| (ColumnBlock::max_abs), with four independent maxima: one running maximum is
// a chain of dependent maxsd, and the sweep needs one per fragment.
double largest_magnitude(const std::vector<double>& values) {
  double lane[4] = {0, 0, 0, 0};
  size_t j = 0;
  for (; j + 4 <= values.size(); j += 4)
    for (int q = 0; q < 4; ++q) lane[q] = std::max(lane[q], std::abs(values[j + q]));
  for (; j < values.size(); ++j) lane[0] = std::max(lane[0], std::abs(values[j]));
  return std::max(std::max(lane[0], lane[1]), std::max(lane[2], lane[3]));
}

}  // namespace

std::vector<double> grid_points(const Discretization& disc) {
  if (disc.grid < 2)
    throw InputError("grid: at least 2 points are needed, got " + std::to_string(disc.grid));
  if (!(disc.lo < disc.hi))
    throw InputError("interval: expected lo < hi, got [" + round_trip(disc.lo) + ", " +
                     round_trip(disc.hi) + "]");
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

ProblemFactory::ProblemFactory(const Basis& basis, const Discretization& disc)
    : basis_(basis), disc_(disc) {
  auto grid = std::make_shared<ColumnBlock>();
  grid->points = grid_points(disc);
  const int n = disc.grid, k = int(basis.size()) + 1;
  if (n < k)
    throw InputError("grid: " + std::to_string(n) + " points, expected at least " +
                     std::to_string(k) + " (the basis's functions plus the constant)");
  if (k > kMaxColumnRows)
    throw InputError("basis: at most " + std::to_string(kMaxColumnRows - 1) + " functions, got " +
                     std::to_string(k - 1));
  rows_ = k;
  // Evaluate (1, b(z_i)) on the grid and orthonormalise: A^T = Q R, rows := R^{-T} A = Q^T.
  // In long double: Eigen has no SIMD packets for it, so its reductions run in one order on every
  // CPU. In double, the QR's vectorised sums followed the SIMD width, and an AVX2 build's grid
  // columns (and so its answers, in their last bits) differed from an AVX-512 build's.
  using Matrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  // (1, b(z)) at the given points, one row per point.
  const auto sample = [&](const std::vector<double>& points) {
    Matrix a(points.size(), k);
    a.col(0).setOnes();
    std::vector<double> values(points.size());
    for (int j = 0; j + 1 < k; ++j) {
      basis[j].evaluate(points, values);
      for (size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(values[i]))
          throw InputError("basis function '" + basis[j].name() +
                           "' is not finite at z = " + round_trip(points[i]));
        a(i, j + 1) = values[i];
      }
    }
    return a;
  };
  Matrix at = sample(grid->points);
  // A window orthonormalises the rows where the distributions live (docs/reference.md §2: a narrow
  // kernel's columns differ only in digits a transform over all of [lo, hi] rounds away).
  const bool windowed = disc.window_lo < disc.window_hi;
  Matrix window_at;
  if (windowed)
    window_at =
        sample(grid_points(Discretization{disc.window_lo, disc.window_hi, std::max(n, 64)}));
  Eigen::HouseholderQR<Matrix> qr(windowed ? window_at : at);
  Matrix r_upper = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
  const long double largest = r_upper.diagonal().cwiseAbs().maxCoeff();
  for (int r = 0; r < k; ++r)
    if (std::abs(r_upper(r, r)) < 1e-12 * largest) {
      std::string names;
      for (const auto& name : basis.names()) names += (names.empty() ? "" : ", ") + name;
      throw InputError("basis {" + names +
                       "} is linearly dependent together with the constant on the grid");
    }
  Matrix t = r_upper.transpose().triangularView<Eigen::Lower>().solve(Matrix::Identity(k, k));
  transform_.resize(size_t(k) * k);
  for (int r = 0; r < k; ++r)
    for (int c = 0; c < k; ++c) transform_[size_t(r) * k + c] = c <= r ? double(t(r, c)) : 0.0;
  Matrix rows = r_upper.transpose().triangularView<Eigen::Lower>().solve(at.transpose());
  grid->values.resize(size_t(k) * n);
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < n; ++i) grid->values[size_t(r) * n + i] = double(rows(r, i));
  grid->max_abs = largest_magnitude(grid->values);
  grid_ = std::move(grid);
}

void ProblemFactory::transform(const double* v, double* out) const {
  for (int r = 0; r < rows_; ++r) {
    double s = 0;
    // Fused, in this order: as `s += t * v`, GCC's vectorised products (a vector multiply, then
    // scalar adds) depended on the SIMD width, and so did the columns' last bits.
    for (int c = 0; c <= r; ++c) s = std::fma(transform_[size_t(r) * rows_ + c], v[c], s);
    out[r] = s;
  }
}

std::vector<long double> ProblemFactory::raw_coefficients(std::span<const long double> y) const {
  std::vector<long double> c(rows_, 0.0L);
  for (int r = 0; r < rows_; ++r)
    for (int k = 0; k <= r; ++k) c[k] += y[r] * (long double)transform_[size_t(r) * rows_ + k];
  return c;
}

void ProblemFactory::column(double z, double* out) const {
  double raw[kMaxColumnRows];
  raw[0] = 1;
  for (size_t j = 0; j < basis_.size(); ++j) {
    raw[j + 1] = basis_[j](z);
    if (!std::isfinite(raw[j + 1]))
      throw InputError("basis function '" + basis_[j].name() +
                       "' is not finite at z = " + round_trip(z));
  }
  transform(raw, out);
}

namespace {

// The block's columns were staged one after the other (column-major, `rows` values each); the
// block stores them row-major, so each row is one contiguous array for pricing.
void finish_block(int rows, const std::vector<double>& staging, ColumnBlock& block) {
  const int n = block.size();
  block.values.resize(size_t(rows) * n);
  for (int j = 0; j < n; ++j)
    for (int r = 0; r < rows; ++r) block.values[size_t(r) * n + j] = staging[size_t(j) * rows + r];
  block.max_abs = largest_magnitude(block.values);
}

// Writes T (1, b(z)) as column `slot` of a row-major block whose rows are `stride` apart.
void put_column(const ProblemFactory& factory, double z, std::vector<double>& values, size_t stride,
                size_t slot) {
  double column[kMaxColumnRows];
  factory.column(z, column);
  for (int r = 0; r < factory.rows(); ++r) values[size_t(r) * stride + slot] = column[r];
}

}  // namespace

void ProblemFactory::add_points(Problem& p, std::span<const double> points) const {
  std::vector<double> added;
  for (double z : points)
    if (std::find(p.extra.points.begin(), p.extra.points.end(), z) == p.extra.points.end() &&
        std::find(added.begin(), added.end(), z) == added.end())
      added.push_back(z);
  if (added.empty()) return;
  const int old_size = p.extra.size(), size = old_size + int(added.size());
  std::vector<double> values(size_t(rows_) * size), column_values(rows_);
  for (int r = 0; r < rows_; ++r)
    for (int e = 0; e < old_size; ++e)
      values[size_t(r) * size + e] = p.extra.values[size_t(r) * old_size + e];
  for (size_t a = 0; a < added.size(); ++a) {
    column(added[a], column_values.data());
    for (int r = 0; r < rows_; ++r) values[size_t(r) * size + old_size + a] = column_values[r];
  }
  p.extra.points.insert(p.extra.points.end(), added.begin(), added.end());
  p.extra.values = std::move(values);
  p.extra.max_abs = largest_magnitude(p.extra.values);
  if (!p.extra_atom.empty()) p.extra_atom.resize(size, -1);
}

Problem ProblemFactory::from_moments(std::span<const double> moments, double zf,
                                     std::span<const double> extra_points) const {
  if (moments.size() != basis_.size())
    throw InputError("moments: expected " + std::to_string(basis_.size()) +
                     " values (one per basis function), got " + std::to_string(moments.size()));
  if (!std::isfinite(zf)) throw InputError("zf: expected a finite depth, got " + round_trip(zf));
  Problem p;
  p.rows = rows_;
  p.grid = grid_;
  p.zf = zf;
  std::vector<double> points;
  for (double z : extra_points) {
    if (!std::isfinite(z)) throw InputError("points: expected finite depths, got " + round_trip(z));
    points.push_back(disc_.quantize ? quantize_to_grid(disc_, z) : z);
  }
  // z_f joins I only where it is admissible; outside [lo, hi] it changes nothing but the cost.
  if (zf >= disc_.lo && zf <= disc_.hi) points.push_back(zf);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<double> staging(points.size() * rows_);
  for (size_t j = 0; j < points.size(); ++j) column(points[j], &staging[j * rows_]);
  p.extra.points = points;
  finish_block(rows_, staging, p.extra);
  std::vector<double> raw(rows_);
  raw[0] = 1;
  for (size_t j = 0; j < moments.size(); ++j) {
    if (!std::isfinite(moments[j]))
      throw InputError("moments: value " + std::to_string(j + 1) + " is " + round_trip(moments[j]) +
                       ", expected a finite number");
    raw[j + 1] = moments[j];
  }
  p.rhs.resize(rows_);
  transform(raw.data(), p.rhs.data());
  p.moments.assign(moments.begin(), moments.end());
  return p;
}

Problem ProblemFactory::from_distribution(std::span<const double> depths,
                                          std::span<const double> weights, double zf) const {
  if (depths.size() != weights.size() || depths.empty())
    throw InputError("distribution: expected as many weights as depths, at least one; got " +
                     std::to_string(weights.size()) + " weights for " +
                     std::to_string(depths.size()) + " depths");
  std::vector<double> columns(depths.size() * rows_);
  std::vector<const double*> pointers(depths.size());
  std::vector<double> used(depths.size());
  for (size_t t = 0; t < depths.size(); ++t) {
    if (!std::isfinite(depths[t]))
      throw InputError("distribution: depth " + std::to_string(t + 1) + " is " +
                       round_trip(depths[t]) + ", expected a finite number");
    used[t] = disc_.quantize ? quantize_to_grid(disc_, depths[t]) : depths[t];
    column(used[t], &columns[t * rows_]);
    pointers[t] = &columns[t * rows_];
  }
  Problem p;
  from_distribution(used, weights, pointers, zf, p);
  return p;
}

namespace {

// The kernel's total weight in four independent sums (one sum is a chain of dependent adds).
double weight_sum(std::span<const double> weights) {
  double part[4] = {0, 0, 0, 0};
  size_t i = 0;
  for (; i + 4 <= weights.size(); i += 4)
    for (int q = 0; q < 4; ++q) part[q] += weights[i + q];
  for (; i < weights.size(); ++i) part[0] += weights[i];
  return (part[0] + part[1]) + (part[2] + part[3]);
}

// Rows written `stride` apart, packed `count` apart: row r moves down from r * stride to r * count.
void pack_rows(std::vector<double>& values, int rows, size_t stride, int count) {
  for (int r = 1; r < rows; ++r)
    std::copy(values.begin() + r * stride, values.begin() + r * stride + count,
              values.begin() + r * count);
  values.resize(size_t(rows) * count);
}

// The untransformed moments, for reports: T (lower triangular) inverted on the rhs.
void untransformed_moments(const std::vector<double>& transform, int rows, const double* rhs,
                           std::vector<double>& moments) {
  moments.resize(rows - 1);
  double raw[kMaxColumnRows];
  for (int r = 0; r < rows; ++r) {
    double s = rhs[r];
    for (int c = 0; c < r; ++c) s -= transform[size_t(r) * rows + c] * raw[c];
    raw[r] = s / transform[size_t(r) * rows + r];
  }
  for (int j = 1; j < rows; ++j) moments[j - 1] = raw[j];
}

}  // namespace

void ProblemFactory::from_distribution(std::span<const double> depths,
                                       std::span<const double> weights,
                                       std::span<const double* const> depth_columns, double zf,
                                       Problem& p) const {
  p.rows = rows_;
  p.grid = grid_;
  p.zf = zf;
  p.extra.points.clear();
  p.start_support.clear();
  p.start_weights.clear();
  p.atom_extra.assign(depths.size(), -1);
  p.extra_atom.clear();
  p.zf_extra = -1;
  const double scale = 1 / weight_sum(weights);  // one division per fragment, not one per atom
  // Distinct depths become extra columns (a kernel often sees one surface many times); the rhs is
  // the distribution's own moment vector, accumulated in atom order (in registers: through p.rhs
  // every atom waited for the previous atom's store). Columns go straight to their rows, `stride`
  // apart (room for every atom and z_f), and the rows are packed at the end.
  double rhs[kMaxColumnRows] = {};
  const size_t atoms = depths.size(), stride = atoms + 1;
  std::vector<double>& values = p.extra.values;
  values.resize(size_t(rows_) * stride);
  // Sized for every atom and z_f, written through pointers, trimmed at the end.
  p.extra.points.resize(stride);
  p.extra_atom.resize(stride);
  p.start_support.resize(atoms);
  p.start_weights.resize(atoms);
  const int g = grid_->size();
  int count = with_row_count<0>(rows_, [&](auto fixed) {
    // The row count known at compile time (0: not), so that rhs stays in registers.
    constexpr int kRows = decltype(fixed)::value;
    const int rows = kRows ? kRows : rows_;
    double* points = p.extra.points.data();
    int* extra_atom = p.extra_atom.data();
    double* start_weights = p.start_weights.data();
    int* start_support = p.start_support.data();
    int* atom_extra = p.atom_extra.data();
    double* out = values.data();
    double sum[kRows ? kRows : kMaxColumnRows] = {};
    int n = 0;
    for (size_t t = 0; t < atoms; ++t) {
      if (weights[t] == 0) continue;
      const double w = weights[t] * scale;
      const double* column = depth_columns[t];
      for (int r = 0; r < rows; ++r)
        sum[r] = std::fma(w, column[r], sum[r]);  // fused: see transform
      // Equal depths are usually neighbours in atom order: look back a few slots only (a duplicate
      // column that slips through is harmless, a quadratic search per fragment is not).
      int slot = -1;  // the earliest match among the last four (selects, not branches)
      for (int back = 4; back >= 1; --back) {
        const int e = n - back;
        slot = e >= 0 && points[e] == depths[t] && slot < 0 ? e : slot;
      }
      if (slot < 0) {
        slot = n++;
        points[slot] = depths[t];
        extra_atom[slot] = int(t);
        for (int r = 0; r < rows; ++r) out[r * stride + slot] = column[r];
        start_support[slot] = g + slot;
        start_weights[slot] = 0;
      }
      start_weights[slot] += w;
      atom_extra[t] = slot;
    }
    for (int r = 0; r < rows; ++r) rhs[r] = sum[r];
    return n;
  });
  p.start_support.resize(count);
  p.start_weights.resize(count);
  p.extra.points.resize(count);
  p.extra_atom.resize(count);
  if (zf >= disc_.lo && zf <= disc_.hi) {
    const auto same = std::find(p.extra.points.begin(), p.extra.points.end(), zf);
    p.zf_extra = int(same - p.extra.points.begin());
    if (same == p.extra.points.end()) {
      p.extra.points.push_back(zf);
      p.extra_atom.push_back(-1);
      put_column(*this, zf, values, stride, count++);
    }
  }
  pack_rows(values, rows_, stride, count);
  p.extra.max_abs = largest_magnitude(values);
  p.rhs.assign(rhs, rhs + rows_);
  untransformed_moments(transform_, rows_, rhs, p.moments);
}

bool ProblemFactory::move_zf(double zf, Problem& p) const {
  const int count = p.extra.size();
  // z_f's own column is the last one exactly when it did not coincide with a kernel depth.
  const bool appended = p.zf_extra >= 0 && p.zf_extra == count - 1 && p.extra_atom[p.zf_extra] < 0;
  if (!appended || !(zf >= disc_.lo && zf <= disc_.hi)) return false;
  if (std::find(p.extra.points.begin(), p.extra.points.end() - 1, zf) != p.extra.points.end() - 1)
    return false;
  put_column(*this, zf, p.extra.values, count, count - 1);
  p.extra.points[count - 1] = zf;
  p.extra.max_abs = largest_magnitude(p.extra.values);
  p.zf = zf;
  return true;
}

Problem make_problem(const Basis& basis, const Discretization& disc,
                     std::span<const double> moments, double zf,
                     std::span<const double> extra_points) {
  return ProblemFactory(basis, disc).from_moments(moments, zf, extra_points);
}

Problem make_problem_from_distribution(const Basis& basis, const Discretization& disc,
                                       std::span<const double> depths,
                                       std::span<const double> weights, double zf) {
  return ProblemFactory(basis, disc).from_distribution(depths, weights, zf);
}

}  // namespace mb::lp
