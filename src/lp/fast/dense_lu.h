#pragma once
// Dense LU with partial pivoting and the explicit inverse of a basis of k <= 8 rows.
#include <algorithm>
#include <cmath>

#include "lp/row_count.h"

namespace mb::lp::fast {

// In-place LU with partial pivoting and inverse for k <= 8, in long double for the certificate's
// last resort: when the double inverse cannot refine x_B and y (cond(B) of boundary instances
// reaches 1e8 and more), the long double one carries ~3 more digits.
// The same routine in double serves every refactorisation: Eigen's general FullPivLU inverse
// cost as much as all pricing passes together at k <= 8 (measured with perf).
// K = k at compile time, so the loops unroll.
template <class Real, int K>
bool invert_fixed(Real a[kMaxRows][kMaxRows], Real inv[kMaxRows][kMaxRows], Real singular) {
  constexpr int k = K;
  int perm[kMaxRows];
  Real reciprocal[kMaxRows];
  for (int i = 0; i < k; ++i) perm[i] = i;
  Real largest = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) largest = std::max(largest, std::abs(a[i][j]));
  for (int c = 0; c < k; ++c) {
    int p = c;
    for (int r = c + 1; r < k; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (std::abs(a[p][c]) <= singular * largest) return false;
    if (p != c) {
      for (int j = 0; j < k; ++j) std::swap(a[p][j], a[c][j]);
      std::swap(perm[p], perm[c]);
    }
    // One division per pivot, not one per entry: divisions have the longest latency of
    // the factorisation's operations.
    reciprocal[c] = Real(1) / a[c][c];
    for (int r = c + 1; r < k; ++r) {
      Real f = a[r][c] *= reciprocal[c];
      for (int j = c + 1; j < k; ++j) a[r][j] -= f * a[c][j];
    }
  }
  for (int col = 0; col < k; ++col) {
    Real v[kMaxRows];
    for (int i = 0; i < k; ++i) v[i] = perm[i] == col ? Real(1) : Real(0);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < i; ++j) v[i] -= a[i][j] * v[j];
    for (int i = k - 1; i >= 0; --i) {
      for (int j = i + 1; j < k; ++j) v[i] -= a[i][j] * v[j];
      v[i] *= reciprocal[i];
    }
    for (int i = 0; i < k; ++i) inv[i][col] = v[i];
  }
  return true;
}

}  // namespace mb::lp::fast
