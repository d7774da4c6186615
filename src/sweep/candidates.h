#pragma once
// Sweep candidates (docs/reference.md §5): every `size`-combination of a catalog of n functions,
// identified by its lexicographic rank among all combinations (ascending index tuples), which is
// stable across runs and machines.
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

uint64_t binomial(int n, int k);
// Lexicographic rank of an ascending combination of indices in [0, n).
uint64_t combination_rank(const std::vector<int>& combination, int n);
std::vector<int> combination_unrank(uint64_t rank, int n, int k);

}  // namespace mb
