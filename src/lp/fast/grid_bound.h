#pragma once
// Binary-search equivalents on a uniform (ascending) grid, O(1) for the grids of Problem 1.
#include <vector>

namespace mb::lp::fast {

inline int grid_bound(const std::vector<double>& grid, double z, bool strict, double scale) {
  const int n = int(grid.size());
  double guess = (z - grid[0]) * scale;
  int i = guess >= 0 ? (guess < n ? int(guess) : n) : 0;  // also maps NaN to 0
  auto before = [&](int j) {
    return strict ? grid[j] <= z : grid[j] < z;
  };  // j is left of the bound
  while (i > 0 && !before(i - 1)) --i;
  while (i < n && before(i)) ++i;
  return i;
}
}  // namespace mb::lp::fast
