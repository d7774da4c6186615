#pragma once
// How much light a part's surface stops (docs/reference.md §7): a constant opacity, optionally
// times a procedural pattern over the surface (3D value noise, for smoke and foliage), so that
// alpha varies inside a filter kernel. A part without the keys is opaque, exactly as before.
#include <cstdint>

#include "util/eigen.h"
#include "util/yaml_reader.h"

namespace mb {

struct OpacityDesc {
  double opacity = 1;        // in [0, 1]
  bool noise = false;        // opacity_pattern: noise
  double scale = 1;          // world units per noise cell
  double low = 0, high = 1;  // the pattern's range: alpha = opacity * (low + (high - low) n(p))
  uint64_t seed = 0;
  bool opaque() const { return opacity >= 1 && !noise; }
  // alpha at world point p.
  double at(const Eigen::Vector3d& p) const;
};

// A part's `opacity` and `opacity_pattern` keys; errors name file, line and key.
OpacityDesc parse_opacity(YamlMap& part);

// Smooth 3D value noise in [0, 1]: seeded lattice values, trilinear with a smoothstep fade.
double value_noise(const Eigen::Vector3d& p, uint64_t seed);

}  // namespace mb
