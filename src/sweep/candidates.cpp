#include "sweep/candidates.h"

#include "util/error.h"

namespace mb {

uint64_t binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  uint64_t r = 1;
  for (int i = 1; i <= k; ++i) r = r * uint64_t(n - k + i) / uint64_t(i);
  return r;
}

// Combinations before `c` in lexicographic order: for each position, those that put a smaller
// index there (with the earlier positions equal).
uint64_t combination_rank(const std::vector<int>& c, int n) {
  const int k = int(c.size());
  uint64_t rank = 0;
  int previous = -1;
  for (int i = 0; i < k; ++i) {
    for (int v = previous + 1; v < c[i]; ++v) rank += binomial(n - v - 1, k - i - 1);
    previous = c[i];
  }
  return rank;
}

std::vector<int> combination_unrank(uint64_t rank, int n, int k) {
  if (rank >= binomial(n, k))
    throw InputError("candidate id " + std::to_string(rank) + ": expected a rank below " +
                     std::to_string(binomial(n, k)) + " (combinations of " + std::to_string(k) +
                     " from " + std::to_string(n) + ")");
  std::vector<int> c;
  int v = 0;
  for (int i = 0; i < k; ++i) {
    for (;; ++v) {
      uint64_t count = binomial(n - v - 1, k - i - 1);
      if (rank < count) break;
      rank -= count;
    }
    c.push_back(v++);
  }
  return c;
}

}  // namespace mb
