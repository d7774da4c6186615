#pragma once
// The receivers of one light view and their PCF reference (REFERENCE.md §3): every fragment of
// every layer that faces the light, each with its depth z_f and PCF over layer 0 with
// receiver-plane depth bias.
#include <cstdint>
#include <span>
#include <vector>

#include "raster/layer_stack.h"
#include "shadow/gaussian_kernel.h"

namespace mb {

struct PcfParams {
  // Compare each tap against z_f + o . grad z_f from the fragment's own triangle plane (Bavoil,
  // seed 001), so planar receivers do not shadow themselves.
  bool receiver_plane = true;
  // Subtracted from the reference depth as well: absorbs curvature and rasterisation rounding.
  double constant_bias = 1e-4;
};

// The ordinary shadow map: layer-0 depth per texel, 1 (the far plane) where the texel is empty.
struct ShadowMap {
  int width = 0, height = 0;
  std::vector<double> depth;
  // Depth at (x, y); outside the map counts as the far plane (REFERENCE.md §3).
  double at(int x, int y) const {
    return x < 0 || y < 0 || x >= width || y >= height ? 1.0 : depth[size_t(y) * width + x];
  }
};
ShadowMap layer0_shadow_map(const LayerStack& stack);

struct Fragments {
  int width = 0, height = 0;
  std::vector<uint32_t> texel;  // row * width + column
  std::vector<uint16_t> layer;  // 0 = the shadow map's own surface
  std::vector<double> zf;       // fragment depth
  std::vector<double> pcf;      // the reference shadow intensity in [0, 1]
  size_t size() const { return zf.size(); }
};

// Receivers in texel order, then layer order; identical for every thread count.
Fragments collect_receivers(const LayerStack& stack, const GaussianKernel& kernel, const PcfParams& pcf,
                            int threads);

// The depth distribution Z the kernel sees around texel (x, y): size^2 layer-0 depths and their
// weights, written to `depths` and `weights` (each kernel.size^2 long), in tap order (rows, then
// columns). With `texels`, also each tap's texel index, or width * height for taps outside the map.
void kernel_distribution(const ShadowMap& map, const GaussianKernel& kernel, int x, int y, std::span<double> depths,
                         std::span<double> weights, std::span<size_t> texels = {});
// F_Z(z) = Z(depth < z) for that distribution (REFERENCE.md §1: strictly less).
double kernel_cdf(const ShadowMap& map, const GaussianKernel& kernel, int x, int y, double z);

}  // namespace mb
