#pragma once
// The scalar references of the lane kernels (lanes.h): compiled in every build, the definition of
// what each SIMD path must return bit for bit (tests/lp_lanes_test.cpp compares them). Every
// fused multiply-add is an explicit std::fma, so a reference gives the same bits whether or not
// the compiler may contract a * b + c.
#include <cmath>
#include <cstdint>
#include <limits>

#include "lp/double_double.h"
#include "lp/row_count.h"

namespace mb::lp::fast::lanes::scalar {

inline constexpr double kNone = std::numeric_limits<double>::infinity();

// The K entries of a row of B, B^-1 or x_B copied, and compared (==: NaN never is).
template <int K>
void copy_row(const double* from, double* to) {
  for (int r = 0; r < K; ++r) to[r] = from[r];
}
template <int K>
bool same_row(const double* a, const double* b) {
  bool same = true;
  for (int r = 0; r < K; ++r) same &= a[r] == b[r];
  return same;
}

// min(0, min_j d[j]); NaN entries never count.
inline double smallest_of(const double* d, int n) {
  double smallest = 0;
  for (int j = 0; j < n; ++j) smallest = d[j] < smallest ? d[j] : smallest;
  return smallest;
}

// Whether some d[j] is below `threshold` or NaN.
inline bool any_below(const double* d, int n, double threshold) {
  bool found = false;
  for (int j = 0; j < n; ++j) found |= !(d[j] >= threshold);
  return found;
}

// The first j with d[j] == value, or -1.
inline int first_holding(const double* d, int n, double value) {
  for (int j = 0; j < n; ++j)
    if (d[j] == value) return j;
  return -1;
}

// Calls f(j), ascending, for every j with d[j] below `threshold` or NaN.
template <class F>
void for_each_below(const double* d, int n, double threshold, F&& f) {
  for (int j = 0; j < n; ++j)
    if (!(d[j] >= threshold)) f(j);
}

// out_j = base_j - sum_r w_r values[r * stride + j] (base 0 when null), one fused chain per column
// from r = 0; returns min(0, min_j out_j). The pricing pass (reduced costs d = c - A^T y) and the
// dual simplex's pivot row.
// (`first_row`: row 0's value when it is the same in every column, else NaN; only the AVX-512
// path uses it, to read row 0 from a register.)
template <int K>
double combine(const double* w, const double* values, size_t stride, const double* base,
               double* out, int n,
               double /*first_row*/ = std::numeric_limits<double>::quiet_NaN()) {
  double smallest = 0;
  for (int j = 0; j < n; ++j) {
    double v = base ? base[j] : 0.0;
    for (int r = 0; r < K; ++r) v = std::fma(-w[r], values[r * stride + j], v);
    out[j] = v;
    smallest = v < smallest ? v : smallest;
  }
  return smallest;
}

// cost[e] = 1 for the points strictly in front of z_f, else 0 (the objective of Problem 1).
inline void front_costs(const double* points, int n, double zf, double* cost) {
  for (int e = 0; e < n; ++e) cost[e] = points[e] < zf ? 1.0 : 0.0;
}

// Row `leave` of B^-1 scaled by `reciprocal`, then every other row i with u_i != 0 less u_i times
// it: the product-form update after a pivot.
template <int K>
void update_inverse(double (*binv)[kMaxRows], int leave, const double* u, double reciprocal) {
  for (int r = 0; r < K; ++r) binv[leave][r] *= reciprocal;
  for (int i = 0; i < K; ++i) {
    if (i == leave || u[i] == 0) continue;
    for (int r = 0; r < K; ++r) binv[i][r] = std::fma(-u[i], binv[leave][r], binv[i][r]);
  }
}

// The points of the basic structural columns (j < n: grid j < g, extra j - g), NaN for the
// others and for positions K..kMaxRows.
template <int K>
void basic_points(const int* basis, int g, int n, const double* grid, const double* extra,
                  double* out) {
  for (int q = 0; q < kMaxRows; ++q)
    out[q] = q < K && basis[q] < n ? (basis[q] < g ? grid[basis[q]] : extra[basis[q] - g])
                                   : std::numeric_limits<double>::quiet_NaN();
}

// The first position q != skip whose point is nearest to z, or -1 (NaN points never are).
template <int K>
int nearest_other(const double* points, double z, int skip) {
  int partner = -1;
  double gap = kNone;
  for (int q = 0; q < K; ++q)
    if (q != skip && std::abs(points[q] - z) < gap) partner = q, gap = std::abs(points[q] - z);
  return partner;
}

// The nearest point strictly beyond `from` in `direction` among positions not in `skip`
// (a bit mask), or direction * infinity. (Only compared with, so the sign of a zero does not
// matter; it is made +0 so that every path returns the same bits.)
template <int K>
double nearest_beyond(const double* points, double from, double direction, unsigned skip) {
  double limit = direction * kNone;
  for (int q = 0; q < K; ++q)
    if (!(skip >> q & 1) && (points[q] - from) * direction > 0 &&
        (limit - points[q]) * direction > 0)
      limit = points[q];
  return limit + 0.0;  // +0 for a zero of either sign: ties of 0 and -0 differ by path
}

// phi(e) = v . column e, one fused chain from r = 0 (columns `stride` apart in `values`).
template <int K>
double fused_dot(const double* v, const double* values, size_t stride, int e) {
  double sum = 0;
  for (int r = 0; r < K; ++r) sum = std::fma(v[r], values[r * stride + e], sum);
  return sum;
}

// Among the extra points strictly inside (lo, hi): the one with phi > 0 farthest from
// `previous` (near), and the one with phi <= 0 nearest to it (far), each the first index on ties,
// or -1. The bracket of a node (bracket_shift.h).
template <int K>
void bracket_extras(const double* v, const double* points, const double* values, int n, double lo,
                    double hi, double previous, int& near, int& far) {
  double near_progress = 0, far_progress = hi - lo;
  near = far = -1;
  for (int e = 0; e < n; ++e) {
    if (!(points[e] > lo && points[e] < hi)) continue;
    const double progress = std::abs(points[e] - previous);
    if (fused_dot<K>(v, values, n, e) > 0) {
      if (progress > near_progress) near_progress = progress, near = e;
    } else if (progress < far_progress) {
      far_progress = progress, far = e;
    }
  }
}

// From grid index g on, in steps of `step`: the first index whose phi = v . column <= 0, or -1 when
// the grid (n points) ends or `limit` is reached first (at or beyond it).
template <int K>
int first_sign_change(const double* v, const double* grid, const double* values, int n, int g,
                      int step, double limit) {
  for (; g >= 0 && g < n; g += step) {
    if ((grid[g] - limit) * step >= 0) return -1;
    if (fused_dot<K>(v, values, n, g) <= 0) return g;
  }
  return -1;
}

// For each query q: the extra point nearest strictly beyond from[q] in direction[q], if strictly
// nearer than distance[q] (the grid's), as out[q] = its index (the first on ties); out[q] is left
// alone otherwise.
template <int Q>
void nearest_beyond_each(const double (&from)[Q], const double (&direction)[Q],
                         const double (&distance)[Q], const double* points, int n, int (&out)[Q]) {
  double nearest[Q];
  int index[Q];
  for (int q = 0; q < Q; ++q) nearest[q] = kNone, index[q] = -1;
  for (int e = 0; e < n; ++e)
    for (int q = 0; q < Q; ++q) {
      const double d = (points[e] - from[q]) * direction[q];
      if (d > 0 && d < nearest[q]) nearest[q] = d, index[q] = e;
    }
  for (int q = 0; q < Q; ++q)
    if (nearest[q] < distance[q]) out[q] = index[q];
}

// The ratio test's step for a column without Harris' relaxation: min over u_i > pivot_tolerance of
// weight_i / u_i (u = B^-1 a, one fused chain per row; weight = max(x_B, 0)), compared as products
// so that one division is taken; infinity when no u_i is large enough.
template <int K>
double blocking_step(const double (*binv)[kMaxRows], const double* weight, const double* a,
                     double pivot_tolerance) {
  double num = kNone, den = 1;
  for (int i = 0; i < K; ++i) {
    double u = 0;
    for (int r = 0; r < K; ++r) u = std::fma(binv[i][r], a[r], u);
    if (u > pivot_tolerance && weight[i] * den < num * u) num = weight[i], den = u;
  }
  return num / den;
}

// The column of a block (values `stride` apart, reduced costs d, indices offset + j) whose step
// lowers the objective most, d_j * blocking_step_j, among d_j < -tolerance: `best` and `column`
// are updated when a column beats `best` strictly (the first on ties).
template <int K>
void greatest_decrease(const double (*binv)[kMaxRows], const double* weight, const double* values,
                       size_t stride, const double* d, int offset, int n, double tolerance,
                       double pivot_tolerance, double& best, int& column) {
  for (int j = 0; j < n; ++j) {
    if (!(d[j] < -tolerance)) continue;
    double a[kMaxRows];
    for (int r = 0; r < K; ++r) a[r] = values[r * stride + j];
    const double theta = blocking_step<K>(binv, weight, a, pivot_tolerance);
    if (!(theta < kNone)) continue;
    if (d[j] * theta < best) best = d[j] * theta, column = offset + j;
  }
}

// misfit = target - B v (Transposed: target - B^T v), each entry one double-double sum rounded
// once; B's columns are basic[i] (entries basic[i][r]).
template <int K, bool Transposed>
void misfit(const double (*basic)[kMaxRows], const DoubleDouble* v, const double* target,
            double* out) {
  DoubleDouble sum[kMaxRows];
  for (int q = 0; q < K; ++q) sum[q] = {target[q], 0};
  if constexpr (Transposed) {
    for (int r = 0; r < K; ++r)
      for (int i = 0; i < K; ++i) add_product(sum[i], v[r], -basic[i][r]);
  } else {
    for (int i = 0; i < K; ++i)
      for (int r = 0; r < K; ++r) add_product(sum[r], v[i], -basic[i][r]);
  }
  for (int q = 0; q < K; ++q) out[q] = sum[q].value();
}

// distance[l] = |zf[l] - to| for the eight lanes of a block of warm bases (NaN for every lane when
// there are none); returns how many are not NaN.
inline int offer_distances(const double* zf, double to, double* distance) {
  int usable = 0;
  for (int l = 0; l < 8; ++l) {
    distance[l] = zf ? std::abs(zf[l] - to) : std::numeric_limits<double>::quiet_NaN();
    usable += distance[l] == distance[l];
  }
  return usable;
}

// The index of the least non-NaN distance[0..n), the first on ties (at least one is not NaN).
inline int closest(const double* distance, int n) {
  int best = 0;
  double least = distance[0];
  for (int i = 1; i < n; ++i) {
    const bool closer = distance[i] < least || least != least;
    least = closer ? distance[i] : least;
    best = closer ? i : best;
  }
  return best;
}

}  // namespace mb::lp::fast::lanes::scalar
