#pragma once
// How eval and sweep cut a view's LP fragments into warm-start runs and where each LP may start
// from (lp::WarmStart): runs are bands of kWarmRunRows shadow-map rows, cut the same way whatever
// thread gets them, so results agree bit for bit for any thread count; inside a run a fragment
// continues its layer's lane (the texel to the left) and offers the texel column's memory (the
// texel above) and the next column's (above and to the right, which the row above has passed).
#include <cstddef>
#include <vector>

#include "lp/solution.h"

namespace mb {

// Shadow-map rows per warm-start run: within a band every row but the first has the row above to
// start from; bands of 8 rows keep 64 runs per 512-row view for the threads to share.
constexpr int kWarmRunRows = 8;
inline int warm_run_of(size_t texel, int width) {
  return int(texel / size_t(width)) / kWarmRunRows;
}
// Where the warm-start runs of `count` fragments in texel order begin, with `count` appended;
// texel_of(i) is the i-th fragment's texel.
template <class TexelOf>
std::vector<size_t> warm_run_begins(size_t count, int width, TexelOf texel_of) {
  std::vector<size_t> begins;
  for (size_t i = 0; i < count; ++i)
    if (i == 0 || warm_run_of(texel_of(i), width) != warm_run_of(texel_of(i - 1), width))
      begins.push_back(i);
  begins.push_back(count);
  return begins;
}

// The kernel's taps between texels (shadow/gaussian_kernel.h's permutation) as the LP's atom map:
// a remembered basis's tap columns come back as the taps that see the same texels.
class KernelAtomMap : public lp::AtomMap {
 public:
  explicit KernelAtomMap(int kernel_size);
  const int* table(lp::Place then, lp::Place now) const override;
  int size() const override { return size_ * size_; }

 private:
  int size_;
  // One permutation per displacement within the kernel's reach; beyond it every tap keeps its
  // index (null).
  std::vector<std::vector<int>> tables_;
};

// The warm start of the fragment at texel (x, y) on `layer` (its lane; layers beyond the lanes
// share the last).
inline lp::WarmStart warm_start_at(int layer, int x, int y, const KernelAtomMap* atoms) {
  lp::WarmStart at;
  at.lane = layer;
  at.memory = x;
  at.offers[0] = x, at.offers[1] = x + 1;
  at.place = {x, y};
  at.atoms = atoms;
  return at;
}

}  // namespace mb
