#include "scene/opacity.h"

#include <cmath>

namespace mb {

namespace {

// SplitMix64's finaliser: a well-mixed 64-bit hash of a lattice point and the seed.
uint64_t mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double lattice(int64_t x, int64_t y, int64_t z, uint64_t seed) {
  uint64_t h = mix(seed + 0x9e3779b97f4a7c15ull);
  h = mix(h ^ uint64_t(x));
  h = mix(h ^ uint64_t(y));
  h = mix(h ^ uint64_t(z));
  return double(h >> 11) * 0x1.0p-53;
}

double fade(double t) {
  return t * t * (3 - 2 * t);
}

}  // namespace

double value_noise(const Eigen::Vector3d& p, uint64_t seed) {
  const double fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int64_t x = int64_t(fx), y = int64_t(fy), z = int64_t(fz);
  const double tx = fade(p.x() - fx), ty = fade(p.y() - fy), tz = fade(p.z() - fz);
  double along_z[2];
  for (int k = 0; k < 2; ++k) {
    double along_y[2];
    for (int j = 0; j < 2; ++j) {
      const double a = lattice(x, y + j, z + k, seed), b = lattice(x + 1, y + j, z + k, seed);
      along_y[j] = a + tx * (b - a);
    }
    along_z[k] = along_y[0] + ty * (along_y[1] - along_y[0]);
  }
  return along_z[0] + tz * (along_z[1] - along_z[0]);
}

double OpacityDesc::at(const Eigen::Vector3d& p) const {
  if (!noise) return opacity;
  return opacity * (low + (high - low) * value_noise(p / scale, seed));
}

OpacityDesc parse_opacity(YamlMap& part) {
  OpacityDesc o;
  o.opacity = part.number("opacity", 1, 0, 1);
  if (!part.has("opacity_pattern")) return o;
  YamlMap pattern = part.map("opacity_pattern");
  pattern.also_suggest({"noise"});
  if (!pattern.has("noise")) {
    pattern.finish();  // names an unknown pattern, with a suggestion
    pattern.fail("", "an opacity_pattern needs one of: noise");
  }
  YamlMap noise = pattern.map("noise");
  o.noise = true;
  o.scale = noise.number("scale", 1, 1e-9, 1e9);
  o.low = noise.number("min", 0, 0, 1);
  o.high = noise.number("max", 1, 0, 1);
  if (o.low > o.high) noise.fail("min", "expected min <= max");
  // A seed is required: two smoke cards with the same implicit seed would look alike.
  if (!noise.has("seed")) noise.fail("seed", "a noise pattern needs a seed (an integer)");
  o.seed = uint64_t(*noise.integer("seed", 0, int64_t(1) << 53));
  noise.finish();
  pattern.finish();
  return o;
}

}  // namespace mb
