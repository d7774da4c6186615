#include "eval/warm_runs.h"

#include "shadow/gaussian_kernel.h"

namespace mb {

KernelAtomMap::KernelAtomMap(int kernel_size) : size_(kernel_size) {
  const int reach = 2 * size_ - 1;
  tables_.resize(size_t(reach) * reach);
  for (int dy = -(size_ - 1); dy < size_; ++dy)
    for (int dx = -(size_ - 1); dx < size_; ++dx)
      tables_[size_t(dy + size_ - 1) * reach + (dx + size_ - 1)] =
          kernel_tap_permutation(size_, dx, dy);
}

const int* KernelAtomMap::table(lp::Place then, lp::Place now) const {
  if (then.x < 0 || then.y < 0 || now.x < 0 || now.y < 0) return nullptr;
  const int dx = now.x - then.x, dy = now.y - then.y;
  if (dx <= -size_ || dx >= size_ || dy <= -size_ || dy >= size_) return nullptr;
  const int reach = 2 * size_ - 1;
  return tables_[size_t(dy + size_ - 1) * reach + (dx + size_ - 1)].data();
}

}  // namespace mb
