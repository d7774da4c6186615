#pragma once
// Problem 1 as a linear program on a finite depth set (REFERENCE.md §2, Algorithm 1):
//   minimise sum_{z_i < z_f} w_i  subject to  sum_i w_i (1, b(z_i)) = (1, b),  w >= 0.
// The m+1 equality rows are orthonormalised over the points before any backend sees them: the
// feasible set is unchanged by an invertible transform of the rows, and the transformed system
// is well conditioned even for badly scaled bases (exp(8z) reaches ~3000, z^5 ~ z^6).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "moments/basis.h"

namespace mb::lp {

// How the admissible set I is discretised (REFERENCE.md §2).
struct Discretization {
  double lo = 0, hi = 1;  // the admissible interval
  int grid = 1024;        // uniform grid points on [lo, hi]
  // false: I = grid ∪ extra points (the kernel's depths) ∪ {z_f}. true: depths are rounded to
  // the grid before moments are taken, and I = grid ∪ {z_f}.
  bool quantize = false;
};

struct Problem {
  std::vector<double> points;   // the depth set I, ascending, distinct
  int rows = 0, cols = 0;       // m + 1, n
  std::vector<double> matrix;   // rows x cols, row-major, orthonormalised rows
  std::vector<double> rhs;      // the moment vector in the same transformed coordinates
  std::vector<uint8_t> cost;    // [points[i] < z_f]
  double zf = 0;
  std::vector<double> moments;  // the untransformed b_1..b_m, for reports
  // A known feasible distribution (indices into points, weights), when the problem was built
  // from one: backends may start from it instead of searching for feasibility.
  std::vector<int> start_support;
  std::vector<double> start_weights;

  double at(int r, int j) const { return matrix[size_t(r) * cols + j]; }
  // The index of `z` in `points`, or -1.
  int index_of(double z) const;
};

// From a given moment vector b (m values), e.g. from `solve --moments`.
Problem make_problem(const Basis& basis, const Discretization& disc, std::span<const double> moments, double zf,
                     std::span<const double> extra_points = {});
// From a depth distribution (the kernel's depths and weights): its points join I, and the moment
// vector is recomputed from them in the transformed coordinates, so that distribution is exactly
// feasible (REFERENCE.md §2: 0 <= G <= F_Z(z_f) then holds without rounding trouble).
Problem make_problem_from_distribution(const Basis& basis, const Discretization& disc, std::span<const double> depths,
                                       std::span<const double> weights, double zf);
// The grid of a discretisation, and rounding to it (quantize mode).
std::vector<double> grid_points(const Discretization& disc);
double quantize_to_grid(const Discretization& disc, double z);

}  // namespace mb::lp
