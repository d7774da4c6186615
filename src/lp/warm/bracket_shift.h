#pragma once
// Bracket shifts: a warm basis's negative weight repaired by moving its pair of points.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// Basic column `i` (negative weight) and the basic point closest to it (its partner) stand for
// one node of the distribution (a basic solution: at most m + 1 points of I, docs/reference.md §2),
// which moved past them since the previous fragment. The pair moves to the node's bracket when
// bracket_node finds it; otherwise towards the node's estimate, the pair's weighted mean (an
// extrapolation while one weight is negative): `i` to the nearest point of I beyond its partner,
// or both to the two points of I around the estimate when it lies further. False, with the basis
// unchanged, when there is no such point, the exchange would be (nearly) singular, or the start
// is hopeless.
template <int K>
inline bool FastSimplex<K>::shift_bracket(int i) {
  const int j = basis_[i];
  // Weights are probabilities: one below -settings_.hopeless_weight means a basis far from any
  // feasible one, and shifts from such starts nearly always ran out of rounds.
  if (j >= n_ || x_[i] < -settings_.hopeless_weight) return false;
  const double z = point(j);
  // Once for the partner and bracket_node's limit (the basis stays until an exchange).
  double points[kMaxRows];
  basic_points(points);
  const int partner = lanes::nearest_other<K>(points, z, i);
  if (partner < 0) return false;
  const double from = points[partner], direction = from > z ? 1.0 : -1.0;
  // A pair whose weights sum to <= 0 stands for no node: a shift only drags the negative weight
  // along, a cell a round (seen in most starts that ran out of rounds). The try fails at once.
  const double mass = x_[i] + x_[partner];
  if (!(mass > 0)) return false;
  if (bracket_node(i, partner, direction, points)) return true;
  const double node = (x_[i] * z + x_[partner] * from) / mass;
  // The point beyond the partner, and the two around the node, in one pass over the extra points
  // (most shifts move both, and one pass reads the extra points once).
  int beyond[3];
  points_beyond<3>({from, node, node}, {direction, direction, -direction},
                   {basis_[partner], -1, -1}, beyond);
  const int next = beyond[0], far = beyond[1], near = beyond[2];
  if (next < 0) return false;
  if ((node - point(next)) * direction > 0) {
    if (far >= 0 && near >= 0 && near != far && exchange(i, far)) {
      exchange(partner, near);  // if refused (basic, or singular), the first half still helps
      return true;
    }
  }
  return exchange(i, next);
}

// The pair (i, partner) replaced by two other points l, m of I, with the other basic columns S
// kept: with v = x_p (row i of B^-1) - x_i (row p of B^-1), orthogonal to the moments and to
// every column of S (rows of B^-1 are orthogonal to the other basic columns), the new weights
// satisfy 0 = v.rhs = w_l phi(l) + w_m phi(m), phi(z) = v.a(z). So they share a sign exactly when
// phi changes sign between l and m: that is the node's bracket, found in one walk. (The estimate
// alone, a Newton step on the node's position, converges slowly where the pair nearly cancels, a
// node of small weight: six shifts and more were common.) phi(z_i) = x_p and phi(z_p) = -x_i are
// both positive, so the walk goes from the partner away from i over grid points to the first with
// phi <= 0, and the extra points between it and the last positive one narrow the bracket. S's
// points are roots of phi too: a walk that would cross one is left to the estimate, as are walks
// that leave the grid and exchanges that would be (nearly) singular (false, basis unchanged; 9 %
// of the calls on lp_bench). On its warm runs at grid 256: 30.4 k shifts instead of 43.5 k, 1.37
// (power4) and 1.34 (trig4) pivots an LP instead of 1.43 and 1.41; at 1024, 1.59 instead of 1.71
// and 1.70.
// `points`: basic_points' of the current basis.
template <int K>
inline bool FastSimplex<K>::bracket_node(int i, int partner, double direction,
                                         const double* points) {
  double v[K];
  for (int r = 0; r < K; ++r) v[r] = x_[partner] * binv_[i][r] - x_[i] * binv_[partner][r];
  const int from_column = basis_[partner], step = direction > 0 ? 1 : -1;
  const double from = point(from_column);
  const auto& grid = p_->grid->points;
  int g = grid_beyond(from, direction, from_column);
  // The walk ends before S's nearest point beyond the partner (a root of phi that is no node's).
  const double limit = lanes::nearest_beyond<K>(points, from, direction, 1u << i | 1u << partner);
  const int first = g;
  g = first_sign_change(v, g, step, limit);
  if (g < 0) return false;
  const double previous = g == first ? from : grid[g - step];
  // The bracket: near (phi > 0: the partner itself or the grid point before g) and far (g), then
  // the extra points strictly between them, the nearest to the sign change on either side.
  int near = g == first ? from_column : g - step, far = g;
  if (near != from_column && is_basic(near)) return false;
  const double lo = std::min(previous, grid[g]), hi = std::max(previous, grid[g]);
  // A narrow kernel's depths crowd into the cell (4.5 judged a call on lp_bench's power4 runs at
  // grid 256), so they are judged in lanes (lanes::bracket_extras).
  int near_extra, far_extra;
  lanes::bracket_extras<K>(v, extra_points_, p_->extra.values.data(), e_, lo, hi, previous,
                           near_extra, far_extra);
  if (near_extra >= 0) near = g_ + near_extra;
  if (far_extra >= 0) far = g_ + far_extra;
  if (!exchange(i, far)) return false;
  // If the second exchange is refused (singular), the first half still helps.
  if (near != from_column) exchange(partner, near);
  return true;
}

// The first grid index strictly beyond `from` in `direction` (-1 or g_ past the ends): the
// neighbour of `column` when that is the grid point at `from` (the grid ascends strictly), else
// by grid_bound.
template <int K>
inline int FastSimplex<K>::grid_beyond(double from, double direction, int column) const {
  const auto& grid = p_->grid->points;
  if (column >= 0 && column < g_) return column + (direction > 0 ? 1 : -1);
  return direction > 0 ? grid_bound(grid, from, true, cell_scale_)
                       : grid_bound(grid, from, false, cell_scale_) - 1;
}

// From grid point g on, in steps of `step`: the first grid point where phi = v.a <= 0, or -1 when
// the grid ends or `limit` is reached first (at or beyond it).
template <int K>
inline int FastSimplex<K>::first_sign_change(const double* v, int g, int step, double limit) const {
  return lanes::first_sign_change<K>(v, grid_points_, p_->grid->values.data(), g_, g, step, limit);
}

// The point of I nearest beyond from[q] in direction[q] (a column index, or -1), for Q queries:
// the grid point of each by grid_bound (or the neighbour of column[q] when that is the grid point
// at from[q]: the grid ascends strictly), then one pass over the extra points for all of them (an
// extra point wins only if strictly nearer), then (without AVX-512) one more for the first index
// holding each nearest distance.
template <int K>
template <int Q>
inline void FastSimplex<K>::points_beyond(const double (&from)[Q], const double (&direction)[Q],
                                          const int (&column)[Q], int (&out)[Q]) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const auto& grid = p_->grid->points;
  double distance[Q];
  for (int q = 0; q < Q; ++q) {
    const int g = grid_beyond(from[q], direction[q], column[q]);
    out[q] = -1, distance[q] = kNone;
    if (g >= 0 && g < g_) out[q] = g, distance[q] = std::abs(grid[g] - from[q]);
  }
  int extra[Q];
  for (int q = 0; q < Q; ++q) extra[q] = -1;
  lanes::nearest_beyond_each<Q>(from, direction, distance, extra_points_, e_, extra);
  for (int q = 0; q < Q; ++q)
    if (extra[q] >= 0) out[q] = g_ + extra[q];
}

// Column `entering` replaces basic column `i`: one product-form update of the inverse and of
// x_B, not a new factorisation. False, with nothing changed, if it is basic already or the
// exchange would be (nearly) singular.
template <int K>
inline bool FastSimplex<K>::exchange(int i, int entering) {
  if (is_basic(entering)) return false;
  // A fresh inverse rather than an end to the shifts: the limit used to stop the first warm
  // basis's shifts in most of the starts that then failed (~85 k of the 119 k composite repairs
  // of a power4 sweep).
  if (updates_ >= refactor_interval() && !refactor()) return false;
  double u[kMaxRows] = {};  // (GCC cannot see that ftran_column fills k_ <= kMaxRows)
  ftran_column(entering, u);
  if (!stable_pivot(u, i)) return false;
  move_along(i, entering, u, x_[i] / u[i]);
  return true;
}

// The points of the basic structural columns by basis position, NaN for the others (the
// composite, artificials) and in out[k..kMaxRows).
template <int K>
inline void FastSimplex<K>::basic_points(double (&out)[kMaxRows]) const {
  lanes::basic_points<K>(basis_, g_, n_, grid_points_, extra_points_, out);
}

}  // namespace mb::lp::fast
