#pragma once
// Problem 1 as a linear program on a finite depth set (docs/reference.md §2, Algorithm 1):
//   minimise sum_{z_i < z_f} w_i  subject to  sum_i w_i (1, b(z_i)) = (1, b),  w >= 0.
// The m+1 equality rows are orthonormalised over the grid before any backend sees them: the
// feasible set is unchanged by an invertible transform of the rows, and the transformed system
// is well conditioned even for badly scaled bases (exp(8z) reaches ~3000, z^5 ~ z^6).
//
// Columns come in two blocks: the grid (shared by every problem of one basis and discretisation,
// built once by a ProblemFactory) and the extra points of one fragment (the kernel's depths and
// z_f). Column j < grid size is a grid column, the rest are extra columns.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "basis/basis.h"

namespace mb::lp {

// The most rows (basis functions plus the constant) a problem may have.
constexpr int kMaxColumnRows = 16;

// How the admissible set I is discretised (docs/reference.md §2).
struct Discretization {
  double lo = 0, hi = 1;  // the admissible interval
  int grid = 1024;        // uniform grid points on [lo, hi]
  // false: I = grid ∪ extra points (the kernel's depths) ∪ {z_f}. true: depths are rounded to
  // the grid before moments are taken, and I = grid ∪ {z_f}.
  bool quantize = false;
  // When window_lo < window_hi, the rows are orthonormalised over a grid on this window instead of
  // the grid on [lo, hi] (the feasible set is the same): verify's local coordinates put a kernel's
  // scale there, so that its columns keep their digits.
  double window_lo = 0, window_hi = 0;
  // Problem 1 on all of [lo, hi] (continuous/discretized.h): the grid then only seeds the exchange.
  bool continuous = false;
  bool operator==(const Discretization&) const = default;
};

// Points and their transformed columns (1, b(z)) -> T (1, b(z)), row-major: values[r * size + j].
struct ColumnBlock {
  std::vector<double> points;
  std::vector<double> values;
  double max_abs = 0;  // the largest |value|, for rounding-error bounds
  int size() const { return int(points.size()); }
};

struct Problem {
  int rows = 0;                             // m + 1
  std::shared_ptr<const ColumnBlock> grid;  // ascending grid points
  ColumnBlock extra;                        // the fragment's own points
  std::vector<double> rhs;                  // the moment vector in the transformed coordinates
  double zf = 0;
  std::vector<double> moments;  // the untransformed b_1..b_m, for reports
  // A known feasible distribution (column indices and weights), when the problem was built from
  // one: backends may start from it instead of searching for feasibility.
  std::vector<int> start_support;
  std::vector<double> start_weights;
  // Built from a distribution (from_distribution): which extra column each atom became, in the
  // order given (-1: zero weight), the first atom of each extra column (-1: the z_f column), and
  // z_f's extra column (-1: none). A warm start maps a remembered basis through these and an
  // AtomMap (solution.h), so that the atoms standing for the same depths come back.
  std::vector<int> atom_extra, extra_atom;
  int zf_extra = -1;
  // The objective's side (docs/reference.md §2, "The maximum"): false counts the mass strictly in
  // front of z_f (G, the sharp lower bound); true the mass strictly behind it, whose minimum m
  // gives the sharp upper bound G+ = 1 - m on the mass at or in front of z_f.
  bool behind = false;
  // Any other linear objective: when not empty, column j's cost (the grid's, then the extra
  // points'), in place of the indicator. The blocker bounds' Dinkelbach steps
  // (lp/blocker_bounds.h) minimise the blockers' depth minus a ratio this way, on Problem 1's
  // feasible set.
  std::vector<double> objective;

  int grid_size() const { return grid ? grid->size() : 0; }
  int cols() const { return grid_size() + extra.size(); }
  double at(int r, int j) const {
    const int g = grid_size();
    return j < g ? grid->values[size_t(r) * g + j]
                 : extra.values[size_t(r) * extra.size() + (j - g)];
  }
  double point(int j) const {
    return j < grid_size() ? grid->points[j] : extra.points[j - grid_size()];
  }
  // The objective: 1 for mass strictly in front of z_f (docs/reference.md §1), or strictly behind
  // it when `behind`.
  double cost(int j) const {
    if (!objective.empty()) return objective[size_t(j)];
    const double z = point(j);
    return (behind ? z > zf : z < zf) ? 1.0 : 0.0;
  }
};

// Everything that depends only on the basis and the discretisation: the grid columns and the row
// transform. Build once, then make many problems (one per fragment) cheaply.
class ProblemFactory {
 public:
  ProblemFactory(const Basis& basis, const Discretization& disc);
  int rows() const { return rows_; }
  const Discretization& discretization() const { return disc_; }
  const Basis& basis() const { return basis_; }
  const std::shared_ptr<const ColumnBlock>& grid() const { return grid_; }
  // T (1, b(z)) for one depth (`out` has rows() values). InputError if b(z) is not finite.
  void column(double z, double* out) const;
  // T v for an untransformed (1, b) vector.
  void transform(const double* untransformed, double* out) const;
  // The coefficients c of y . T (1, b(z)) = c_0 + sum_j c_j b_j(z): a dual vector of the
  // transformed rows as a function of z (T^T y, in long double).
  std::vector<long double> raw_coefficients(std::span<const long double> y) const;

  // From a given moment vector b (m values), e.g. from `solve --moments`.
  Problem from_moments(std::span<const double> moments, double zf,
                       std::span<const double> extra_points = {}) const;
  // From a depth distribution (the kernel's depths and weights): its depths join I, and the
  // moment vector is recomputed from them in the transformed coordinates, so that distribution
  // is exactly feasible (docs/reference.md §2: 0 <= G <= F_Z(z_f) then holds without rounding
  // trouble).
  Problem from_distribution(std::span<const double> depths, std::span<const double> weights,
                            double zf) const;
  // The same, with the depths' transformed columns already known (the sweep computes them once per
  // texel): column(depths[t]) == depth_columns[t]. Reuses `out`'s storage.
  void from_distribution(std::span<const double> depths, std::span<const double> weights,
                         std::span<const double* const> depth_columns, double zf,
                         Problem& out) const;
  // `p`, built by from_distribution, for another z_f (e.g. the fragments of one texel, which share
  // its kernel): only z_f's column changes, and `p` ends up as from_distribution would build it.
  // False, with `p` unchanged, when z_f's column is not simply replaced (z_f on a kernel depth or
  // outside [lo, hi], before or now): then build anew.
  bool move_zf(double zf, Problem& p) const;
  // Appends `points` (those not already among p's extra points) to p's extra columns, with no
  // atom behind them: more of I, so G can only fall (docs/reference.md §2). Verify adds a closed
  // form's extremal support this way where it lies beyond the grid's interval.
  void add_points(Problem& p, std::span<const double> points) const;

 private:
  Basis basis_;
  Discretization disc_;
  int rows_ = 0;
  std::vector<double> transform_;  // rows x rows, row-major, lower triangular (R^{-T})
  std::shared_ptr<const ColumnBlock> grid_;
};

// One-off conveniences (build a factory each time).
Problem make_problem(const Basis& basis, const Discretization& disc,
                     std::span<const double> moments, double zf,
                     std::span<const double> extra_points = {});
Problem make_problem_from_distribution(const Basis& basis, const Discretization& disc,
                                       std::span<const double> depths,
                                       std::span<const double> weights, double zf);
// The grid of a discretisation, and rounding to it (quantize mode).
std::vector<double> grid_points(const Discretization& disc);
double quantize_to_grid(const Discretization& disc, double z);

}  // namespace mb::lp
