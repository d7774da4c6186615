#include "raster/layer_stack.h"

#include <algorithm>

namespace mb {

bool LayerStack::same_fragments(const LayerStack& o) const {
  return width == o.width && height == o.height && offsets == o.offsets && depth == o.depth &&
         facing == o.facing && dz_dx == o.dz_dx && dz_dy == o.dz_dy && alpha == o.alpha;
}

LayerStackStats compute_stats(const LayerStack& stack, size_t triangles) {
  LayerStackStats stats;
  stats.triangles = triangles;
  stats.fragments = stack.fragment_count();
  for (uint8_t f : stack.facing) stats.receivers += f;
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    int n = stack.layers(t);
    stats.covered_texels += n > 0;
    stats.max_layers = std::max(stats.max_layers, n);
  }
  stats.mean_layers =
      stats.covered_texels ? double(stats.fragments) / double(stats.covered_texels) : 0;
  return stats;
}

}  // namespace mb
