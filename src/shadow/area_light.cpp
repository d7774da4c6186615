#include "shadow/area_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mb {

namespace {

// Van der Corput's radical inverse of i in base 2: the bits of i mirrored about the binary point.
double radical_inverse2(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return double(i) * 0x1p-32;
}

// Shirley and Chiu's concentric map of [0, 1]^2 onto the unit disk: area-preserving, so uniform
// (and stratified) points stay uniform (and stratified) on the light's disk.
Eigen::Vector2d concentric_disk(double u, double v) {
  const double a = 2 * u - 1, b = 2 * v - 1;
  if (a == 0 && b == 0) return {0, 0};
  const double quarter = std::numbers::pi / 4;
  if (std::abs(a) > std::abs(b))
    return {a * std::cos(quarter * b / a), a * std::sin(quarter * b / a)};
  return {b * std::cos(2 * quarter - quarter * a / b), b * std::sin(2 * quarter - quarter * a / b)};
}

// The texels every sheared receiver may move plus the kernel's reach, so none leaves the map.
int shear_pad(const std::vector<Eigen::Vector2d>& shears, int kernel_radius) {
  double reach = 0;
  for (const auto& s : shears) reach = std::max({reach, std::abs(s.x()), std::abs(s.y())});
  return reach == 0 ? 0 : int(std::ceil(reach / 2)) + kernel_radius + 1;
}

}  // namespace

double rim_shear(const LightFrame& frame, double angle_deg) {
  const double half = angle_deg * std::numbers::pi / 360;
  return std::tan(half) * frame.world_per_depth() / frame.world_per_texel();
}

std::vector<Eigen::Vector2d> light_shears(const LightFrame& frame, const AreaLight& light) {
  // A light of no extent has one direction: the view itself (docs/soft-shadows.md §1).
  if (light.angle_deg == 0) return {Eigen::Vector2d(0, 0)};
  const double rim = rim_shear(frame, light.angle_deg);
  std::vector<Eigen::Vector2d> shears;
  for (int i = 0; i < light.directions; ++i) {
    const Eigen::Vector2d d =
        concentric_disk((i + 0.5) / light.directions, radical_inverse2(uint32_t(i)));
    // Raster y grows downwards while the frame's v grows up (scene/light_view.h).
    shears.emplace_back(rim * d.x(), -rim * d.y());
  }
  return shears;
}

AreaLightShadow area_light_shadow(const Scene& scene, const LightViewDesc& view,
                                  const Fragments& fragments, const std::vector<double>& gx,
                                  const std::vector<double>& gy, const GaussianKernel& kernel,
                                  const BiasParams& bias, const AreaLight& light, int threads) {
  const LightFrame frame(view, scene.mesh.vertices);
  const std::vector<Eigen::Vector2d> shears = light_shears(frame, light);
  const int pad = shear_pad(shears, kernel.radius());
  const size_t count = fragments.size();
  AreaLightShadow out;
  out.shadow.assign(count, 0.0);
  out.covered_taps.assign(count, 0);
  out.taps = fragments.kernel_taps * int(shears.size());
  out.rim_shear = rim_shear(frame, light.angle_deg);
  for (const Eigen::Vector2d& s : shears) {
    const RasterShear shear{s.x(), s.y(), pad};
    const ShadowMap map = layer0_shadow_map(render_view(scene, view, threads, shear));
#pragma omp parallel for schedule(static) num_threads(threads)
    for (size_t k = 0; k < count; ++k) {
      const size_t t = fragments.texel[k];
      const double zf = fragments.zf[k];
      // The receiver's plane z = zf + g . (dx, dy) in the sheared raster: dx' = dx + s dz gives
      // g' = g / (1 + g . s). At or below 0 the direction lies behind the receiver's own plane,
      // which it therefore does not light (an attached shadow).
      const double facing = 1 + gx[k] * s.x() + gy[k] * s.y();
      if (!(facing > 0)) {
        out.shadow[k] += 1;
        out.covered_taps[k] += uint32_t(fragments.kernel_taps);
        continue;
      }
      const Eigen::Vector3d p =
          shear.apply({double(t % fragments.width) + 0.5, double(t / fragments.width) + 0.5, zf});
      const int x = int(std::floor(p.x())), y = int(std::floor(p.y()));
      const double sgx = gx[k] / facing, sgy = gy[k] / facing;
      const double z = zf + sgx * ((x + 0.5) - p.x()) + sgy * ((y + 0.5) - p.y());
      const ReceiverTest test = receiver_test(map, kernel, bias, x, y, z, sgx, sgy);
      out.shadow[k] += test.pcf;
      out.covered_taps[k] += uint32_t(test.covered_taps);
    }
  }
  const double n = double(shears.size());
  for (double& v : out.shadow) v /= n;
  return out;
}

SoftReceivers light_receivers(const Scene& scene, const LightViewDesc& view, Fragments& fragments,
                              std::vector<double> gx, std::vector<double> gy,
                              const GaussianKernel& kernel, const BiasParams& bias,
                              const AreaLight& light, int threads) {
  AreaLightShadow area =
      area_light_shadow(scene, view, fragments, gx, gy, kernel, bias, light, threads);
  SoftReceivers soft;
  soft.angle_deg = light.angle_deg;
  soft.rim_shear = area.rim_shear;
  soft.gx = std::move(gx);
  soft.gy = std::move(gy);
  soft.hard = std::move(fragments.pcf);
  fragments.pcf = std::move(area.shadow);
  fragments.covered_taps = std::move(area.covered_taps);
  fragments.kernel_taps = area.taps;
  return soft;
}

SoftReceivers light_receivers(const Scene& scene, const LightViewDesc& view,
                              const LayerStack& central, Fragments& fragments,
                              const GaussianKernel& kernel, const BiasParams& bias,
                              const AreaLight& light, int threads) {
  std::vector<double> gx(fragments.size()), gy(fragments.size());
  for (size_t k = 0; k < fragments.size(); ++k) {
    const uint64_t i = central.offsets[fragments.texel[k]] + fragments.layer[k];
    gx[k] = central.dz_dx[i];
    gy[k] = central.dz_dy[i];
  }
  return light_receivers(scene, view, fragments, std::move(gx), std::move(gy), kernel, bias, light,
                         threads);
}

}  // namespace mb
