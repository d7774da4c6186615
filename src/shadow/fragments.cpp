#include "shadow/fragments.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace mb {

const char* reference_name(Reference reference) {
  return reference == Reference::Biased ? "biased" : "receiver_plane";
}

Reference parse_reference(const std::string& text, const std::string& key) {
  if (text == "biased") return Reference::Biased;
  if (text == "receiver_plane") return Reference::ReceiverPlane;
  throw InputError(key + ": expected biased or receiver_plane, got '" + text + "'");
}

double fragment_bias(const BiasParams& bias, int kernel_radius, double dz_dx, double dz_dy) {
  return bias.constant + bias.slope * kernel_radius * (std::abs(dz_dx) + std::abs(dz_dy));
}

ShadowMap layer0_shadow_map(const LayerStack& stack) {
  ShadowMap map;
  map.width = stack.width;
  map.height = stack.height;
  map.depth.resize(stack.texel_count());
  for (size_t t = 0; t < stack.texel_count(); ++t) map.depth[t] = stack.layer0_depth(t);
  return map;
}

Fragments collect_receivers(const LayerStack& stack, const GaussianKernel& kernel,
                            const BiasParams& bias, int threads) {
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
  f.ztest.resize(count);
  f.oracle.resize(count);
  f.pcf.resize(count);
  const ShadowMap map = layer0_shadow_map(stack);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (size_t k = 0; k < count; ++k) {
    const size_t t = f.texel[k];
    const uint64_t i = stack.offsets[t] + f.layer[k];
    const int x = int(t % stack.width), y = int(t / stack.width);
    const ReceiverTest test =
        receiver_test(map, kernel, bias, x, y, stack.depth[i], stack.dz_dx[i], stack.dz_dy[i]);
    f.zf[k] = stack.depth[i];
    f.ztest[k] = test.ztest;
    f.oracle[k] = test.oracle;
    f.pcf[k] = test.pcf;
  }
  return f;
}

ReceiverTest receiver_test(const ShadowMap& map, const GaussianKernel& kernel,
                           const BiasParams& bias, int x, int y, double zf, double gx, double gy) {
  const int r = kernel.radius();
  const double ztest = zf - fragment_bias(bias, r, gx, gy);
  double oracle = 0, plane = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const double depth = map.at(x + dx, y + dy), w = kernel.weight(dx, dy);
      if (depth < ztest) oracle += w;
      // docs/reference.md §3: the ideal filtered hard shadow tests each tap against the plane. The
      // plane, extrapolated past a steep receiver's edge, can pass the far plane, where empty
      // texels hold depth 1: nothing lies beyond it, so the test depth stops there.
      if (depth < std::min(zf + dx * gx + dy * gy - bias.constant, 1.0)) plane += w;
    }
  oracle = std::min(oracle, 1.0);
  return {ztest, oracle, bias.reference == Reference::Biased ? oracle : std::min(plane, 1.0)};
}

void kernel_distribution(const ShadowMap& map, const GaussianKernel& kernel, int x, int y,
                         std::span<double> depths, std::span<double> weights,
                         std::span<size_t> texels) {
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

}  // namespace mb
