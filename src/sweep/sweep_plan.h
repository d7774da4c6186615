#pragma once
// Which candidates a sweep evaluates (docs/reference.md §5): all `size`-combinations of a catalog,
// an explicit list, or a seeded random sample; and the deterministic share of one shard.
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

class TechniqueParams;

struct SweepPlan {
  std::vector<std::string> catalog;  // function names, in catalog order (ranks use this order)
  int size = 4;
  std::vector<uint64_t> ids;  // ascending candidate ranks
  uint64_t total() const;     // C(catalog, size)
  std::vector<std::string> functions(uint64_t id) const;
  std::string name(uint64_t id) const;  // "z; z^2; z^3; z^4"
};

// `explicit_candidates`: each "f1; f2; ..." (functions of the catalog). `sample` > 0 draws that
// many distinct candidates with `seed`, and the explicit ones join them; neither: all. InputError
// on a catalog smaller than `size`, unknown or repeated functions.
SweepPlan make_sweep_plan(const std::vector<std::string>& catalog, int size,
                          const std::vector<std::string>& explicit_candidates, uint64_t sample,
                          uint64_t seed);
// Before any work, InputError when a candidate of the plan could not be evaluated: a catalog
// function not admissible on [lp.lo, lp.hi] (a pole would fail every candidate it is in), an
// expression under a unorm lp.moment_box (which needs certified ranges), or more functions than
// lp.backend takes.
void check_plan(const SweepPlan& plan, const TechniqueParams& technique);
// Shard k of n (1-based): every n-th candidate of the plan, starting at the (k-1)-th.
std::vector<uint64_t> shard_ids(const SweepPlan& plan, int k, int n);
// "K/N" -> (K, N), InputError otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace mb
