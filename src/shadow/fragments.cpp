#include "shadow/fragments.h"

#include <omp.h>

namespace mb {

ShadowMap layer0_shadow_map(const LayerStack& stack) {
  ShadowMap map;
  map.width = stack.width;
  map.height = stack.height;
  map.depth.resize(stack.texel_count());
  for (size_t t = 0; t < stack.texel_count(); ++t) map.depth[t] = stack.layer0_depth(t);
  return map;
}

Fragments collect_receivers(const LayerStack& stack, const GaussianKernel& kernel, const PcfParams& pcf,
                            int threads) {
  Fragments f;
  f.width = stack.width;
  f.height = stack.height;
  for (size_t t = 0; t < stack.texel_count(); ++t)
    for (uint64_t i = stack.offsets[t]; i < stack.offsets[t + 1]; ++i)
      if (stack.facing[i]) {
        f.texel.push_back(uint32_t(t));
        f.layer.push_back(uint16_t(i - stack.offsets[t]));
      }
  const size_t count = f.texel.size();
  f.zf.resize(count);
  f.pcf.resize(count);
  const ShadowMap map = layer0_shadow_map(stack);
  const int r = kernel.radius();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (size_t k = 0; k < count; ++k) {
    const size_t t = f.texel[k];
    const uint64_t i = stack.offsets[t] + f.layer[k];
    const int x = int(t % stack.width), y = int(t / stack.width);
    const double zf = stack.depth[i];
    const double gx = pcf.receiver_plane ? stack.dz_dx[i] : 0.0, gy = pcf.receiver_plane ? stack.dz_dy[i] : 0.0;
    double shadow = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        double reference = zf + dx * gx + dy * gy - pcf.constant_bias;
        if (map.at(x + dx, y + dy) < reference) shadow += kernel.weight(dx, dy);
      }
    f.zf[k] = zf;
    f.pcf[k] = std::min(shadow, 1.0);
  }
  return f;
}

void kernel_distribution(const ShadowMap& map, const GaussianKernel& kernel, int x, int y, std::span<double> depths,
                         std::span<double> weights, std::span<size_t> texels) {
  const int r = kernel.radius();
  size_t k = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx, ++k) {
      depths[k] = map.at(x + dx, y + dy);
      weights[k] = kernel.weight(dx, dy);
      if (texels.empty()) continue;
      const int xx = x + dx, yy = y + dy;
      const bool inside = xx >= 0 && yy >= 0 && xx < map.width && yy < map.height;
      texels[k] = inside ? size_t(yy) * map.width + xx : map.depth.size();
    }
}

double kernel_cdf(const ShadowMap& map, const GaussianKernel& kernel, int x, int y, double z) {
  const int r = kernel.radius();
  double total = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (map.at(x + dx, y + dy) < z) total += kernel.weight(dx, dy);
  return total;
}

}  // namespace mb
