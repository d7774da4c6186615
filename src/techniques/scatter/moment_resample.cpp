#include "techniques/scatter/moment_resample.h"

#include <algorithm>
#include <cmath>

namespace mb {

namespace {

constexpr double kEmpty[3] = {1, 1, 1};  // the moments of depth 1: no surface

}  // namespace

TwoDepths two_depths(double b1, double b2, double b3) {
  TwoDepths one;
  one.depth[0] = one.depth[1] = b1;
  // Seed 004 §2.3, Algorithm 1: with z_1 of the three-depth distribution through the first four
  // moments gone to infinity, the other two are the roots of c2 z² + c1 z + c0.
  const double c2 = b2 - b1 * b1, c1 = b1 * b2 - b3, c0 = -b1 * c1 - b2 * c2;
  if (!(c2 > kMinResampleVariance)) return one;
  // The roots without cancellation: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2 and c0 / q.
  // The discriminant is positive for a positive variance; rounding may leave it just below 0.
  const double root = std::sqrt(std::max(c1 * c1 - 4 * c2 * c0, 0.0));
  const double q = -0.5 * (c1 + std::copysign(root, c1));
  double z2 = q / c2, z3 = q != 0 ? c0 / q : z2;
  if (z2 > z3) std::swap(z2, z3);
  if (!(z3 > z2) || !std::isfinite(z2) || !std::isfinite(z3)) return one;
  // The weights from the first moment (the zeroth, 1, fixes their sum); the mean lies between the
  // two roots of an exact distribution, rounding may push it a hair outside.
  const double w3 = std::clamp((b1 - z2) / (z3 - z2), 0.0, 1.0);
  TwoDepths two;
  two.depth[0] = z2, two.depth[1] = z3;
  two.weight[0] = 1 - w3, two.weight[1] = w3;
  return two;
}

LightMomentMap::LightMomentMap(const LightDepthMap& light) {
  Level base;
  base.size = light.resolution;
  base.moments.resize(size_t(base.size) * base.size * 3);
  for (size_t t = 0; t < light.depth.size(); ++t) {
    const double z = std::isinf(light.depth[t]) ? 1.0 : light.depth[t];
    base.moments[3 * t] = z, base.moments[3 * t + 1] = z * z, base.moments[3 * t + 2] = z * z * z;
  }
  levels_.push_back(std::move(base));
  // Level k's texel i covers level 0's texels [i 2^k, (i + 1) 2^k); the parts of a texel beyond
  // the map (odd sizes) are empty, as everything outside the map is.
  while (levels_.back().size > 1) {
    const Level& below = levels_.back();
    Level next;
    next.size = (below.size + 1) / 2;
    next.moments.resize(size_t(next.size) * next.size * 3);
    for (int y = 0; y < next.size; ++y)
      for (int x = 0; x < next.size; ++x)
        for (int j = 0; j < 3; ++j) {
          double sum = 0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              const int bx = 2 * x + dx, by = 2 * y + dy;
              sum += bx < below.size && by < below.size
                         ? below.moments[(size_t(by) * below.size + bx) * 3 + j]
                         : kEmpty[j];
            }
          next.moments[(size_t(y) * next.size + x) * 3 + j] = 0.25 * sum;
        }
    levels_.push_back(std::move(next));
  }
}

void LightMomentMap::bilinear(int level, double x, double y, double out[3]) const {
  const Level& l = levels_[size_t(level)];
  const double scale = std::ldexp(1.0, -level);  // level-0 texels to this level's
  const double fx = x * scale - 0.5, fy = y * scale - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double ax = fx - x0, ay = fy - y0;
  out[0] = out[1] = out[2] = 0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
      const double tx = x0 + dx, ty = y0 + dy;
      const bool inside = tx >= 0 && ty >= 0 && tx < l.size && ty < l.size;
      const double* m =
          inside ? &l.moments[(size_t(ty) * size_t(l.size) + size_t(tx)) * 3] : kEmpty;
      for (int j = 0; j < 3; ++j) out[j] += w * m[j];
    }
}

void LightMomentMap::sample(double x, double y, double footprint, double out[3]) const {
  const int top = levels() - 1;
  const double lod = footprint > 1 ? std::log2(footprint) : 0;
  const int lo = std::min(int(lod), top);
  const double f = lo < top ? lod - lo : 0;
  bilinear(lo, x, y, out);
  if (!(f > 0)) return;
  double upper[3];
  bilinear(lo + 1, x, y, upper);
  for (int j = 0; j < 3; ++j) out[j] += f * (upper[j] - out[j]);
}

}  // namespace mb
