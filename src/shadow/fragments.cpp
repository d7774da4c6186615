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

namespace {

// Each texel's distribution of where its light stops (docs/reference.md §7): front to back, a
// surface takes alpha of the light that reached it; the first opaque one takes the rest, else the
// far plane does.
void add_translucent_atoms(const LayerStack& stack, ShadowMap& map) {
  map.atom_offsets.assign(stack.texel_count() + 1, 0);
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    double transmitted = 1;
    for (uint64_t i = stack.offsets[t]; i < stack.offsets[t + 1] && transmitted > 0; ++i) {
      const double alpha = stack.alpha[i];
      if (alpha <= 0) continue;  // a fully transparent surface stops nothing
      map.atom_depth.push_back(stack.depth[i]);
      map.atom_mass.push_back(alpha >= 1 ? transmitted : transmitted * alpha);
      map.atom_alpha.push_back(std::min(alpha, 1.0));
      transmitted = alpha >= 1 ? 0 : transmitted * (1 - alpha);
    }
    if (transmitted > 0) {
      map.atom_depth.push_back(1.0);
      map.atom_mass.push_back(transmitted);
      map.atom_alpha.push_back(0.0);
    }
    map.atom_offsets[t + 1] = map.atom_depth.size();
  }
}

// The masses an unsorted blend gives the same atoms (docs/reference.md §7): the opaque pass leaves
// the texel's last atom (its first opaque surface or the far plane) with everything; each
// translucent surface in front, drawn in triangle order, takes alpha of the blend ("over") and
// leaves 1 - alpha of what was there. A convex combination at every step, so the result is again a
// distribution on the same atoms, with masses that depend on the order.
void add_submission_masses(const LayerStack& stack, ShadowMap& map) {
  if (stack.triangle.size() != stack.fragment_count())
    throw InputError("translucent.blend: submission order needs the stack's triangles");
  map.atom_blend.assign(map.atom_mass.size(), 0.0);
  map.atom_draw.assign(map.atom_mass.size(), 0);
  struct Drawn {
    uint32_t triangle;
    uint64_t atom;
    double alpha;
    bool operator<(const Drawn& o) const { return triangle < o.triangle; }
  };
  std::vector<Drawn> drawn;
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    const uint64_t first = map.atom_offsets[t], last = map.atom_offsets[t + 1] - 1;
    drawn.clear();
    uint64_t a = first;  // the atoms in front of the last, in depth order (add_translucent_atoms)
    for (uint64_t i = stack.offsets[t]; i < stack.offsets[t + 1] && a < last; ++i)
      if (stack.alpha[i] > 0) drawn.push_back({stack.triangle[i], a++, double(stack.alpha[i])});
    std::stable_sort(drawn.begin(), drawn.end());
    map.atom_blend[last] = 1;
    map.atom_draw[first] = last;
    for (size_t k = 0; k < drawn.size(); ++k) {
      const Drawn& d = drawn[k];
      for (uint64_t b = first; b <= last; ++b) map.atom_blend[b] *= 1 - d.alpha;
      map.atom_blend[d.atom] = d.alpha;
      map.atom_draw[first + 1 + k] = d.atom;
    }
  }
}

}  // namespace

ShadowMap layer0_shadow_map(const LayerStack& stack, BlendOrder order) {
  ShadowMap map;
  map.width = stack.width;
  map.height = stack.height;
  map.depth.resize(stack.texel_count());
  for (size_t t = 0; t < stack.texel_count(); ++t) map.depth[t] = stack.layer0_depth(t);
  if (stack.translucent()) add_translucent_atoms(stack, map);
  if (stack.translucent() && order == BlendOrder::Submission) add_submission_masses(stack, map);
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
  f.covered_taps.resize(count);
  f.kernel_taps = kernel.size * kernel.size;
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
    f.covered_taps[k] = uint32_t(test.covered_taps);
  }
  return f;
}

double texel_cdf(const ShadowMap& map, int x, int y, double z) {
  if (!map.translucent() || x < 0 || y < 0 || x >= map.width || y >= map.height)
    return map.at(x, y) < z ? 1 : 0;
  const size_t t = size_t(y) * map.width + x;
  double cdf = 0;
  for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a)
    if (map.atom_depth[a] < z) cdf += map.atom_mass[a];
  return cdf;
}

ReceiverTest receiver_test(const ShadowMap& map, const GaussianKernel& kernel,
                           const BiasParams& bias, int x, int y, double zf, double gx, double gy) {
  const int r = kernel.radius();
  const double ztest = zf - fragment_bias(bias, r, gx, gy);
  double oracle = 0, plane = 0;
  int covered = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const double w = kernel.weight(dx, dy), cdf = texel_cdf(map, x + dx, y + dy, ztest);
      oracle += w * cdf;
      covered += cdf > 0;
      // docs/reference.md §3: the ideal filtered hard shadow tests each tap against the plane. The
      // plane, extrapolated past a steep receiver's edge, can pass the far plane, where empty
      // texels hold depth 1: nothing lies beyond it, so the test depth stops there.
      plane +=
          w * texel_cdf(map, x + dx, y + dy, std::min(zf + dx * gx + dy * gy - bias.constant, 1.0));
    }
  oracle = std::min(oracle, 1.0);
  return {ztest, oracle, bias.reference == Reference::Biased ? oracle : std::min(plane, 1.0),
          covered};
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

void kernel_atoms(const ShadowMap& map, const GaussianKernel& kernel, int x, int y,
                  std::vector<double>& depths, std::vector<double>& weights,
                  std::vector<size_t>* atoms, std::vector<uint32_t>* tap_offsets,
                  std::vector<double>* alphas) {
  const int r = kernel.radius();
  depths.clear(), weights.clear();
  if (atoms) atoms->clear();
  if (alphas) alphas->clear();
  if (tap_offsets) tap_offsets->assign(1, 0);
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int xx = x + dx, yy = y + dy;
      const double w = kernel.weight(dx, dy);
      const bool inside = xx >= 0 && yy >= 0 && xx < map.width && yy < map.height;
      const size_t t = inside ? size_t(yy) * map.width + xx : 0;
      if (!inside || !map.translucent()) {
        depths.push_back(inside ? map.depth[t] : 1.0);
        weights.push_back(w);
        if (atoms) atoms->push_back(inside ? t : map.atom_count());
        if (alphas) alphas->push_back(inside && map.depth[t] < 1 ? 1.0 : 0.0);
      } else {
        for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a) {
          depths.push_back(map.atom_depth[a]);
          weights.push_back(w * map.blended_mass()[a]);
          if (atoms) atoms->push_back(a);
          if (alphas) alphas->push_back(map.atom_alpha[a]);
        }
      }
      if (tap_offsets) tap_offsets->push_back(uint32_t(depths.size()));
    }
}

}  // namespace mb
