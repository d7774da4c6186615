#pragma once
// A filtered moment map (docs/design.md §Data flow): b(layer-0 depth) per texel, stored as the
// chosen storage would hold it, filtered by the same normalised Gaussian as PCF (separably, in
// double), then loaded back. The texel's value is b = E_Z[b] of its kernel distribution
// (docs/reference.md §1).
#include <span>
#include <vector>

#include "basis/basis.h"
#include "moments/storage.h"
#include "shadow/fragments.h"
#include "shadow/gaussian_kernel.h"

namespace mb {

struct MomentMap {
  int width = 0, height = 0, m = 0;
  std::vector<double> values;  // texel-major, m per texel
  std::span<const double> at(size_t texel) const { return {values.data() + texel * m, size_t(m)}; }
};

MomentMap compute_moment_map(const ShadowMap& map, const Basis& basis, const GaussianKernel& kernel,
                             const MomentStorage& storage, int threads);

}  // namespace mb
