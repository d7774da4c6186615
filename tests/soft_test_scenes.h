#pragma once
// The half-plane scene of the soft-shadow tests: a thin square slab 1.01 above a ground plane, its
// edge along the world's z axis at x = 0, lit straight down.
#include <string>

#include "scene/scene.h"
#include "test_support.h"

namespace mb::testing_support {

// `margin` 0 puts the ground at depth 1 and the slab's edge on a texel boundary; an elevation
// below 90 degrees tilts both in light space, so the receivers have a depth gradient.
inline Scene slab_scene(int resolution, double margin, double elevation = 90) {
  return build_scene(
      parse_scene(write_temp_file("slab.yaml", R"(
name: slab
parts:
  - ground_plane: {size: 8}
  - box: {size: [4, 0.01, 4]}
    transform: {translate: [-2, 1, 0]}
views:
  - {name: top, azimuth: 0, elevation: )" + std::to_string(elevation) +
                                                   ", resolution: " + std::to_string(resolution) +
                                                   ", margin: " + std::to_string(margin) + "}\n")));
}

}  // namespace mb::testing_support
