#pragma once
// What a camera sees of a scene (issue 34's camera views): per pixel the nearest surface's scene
// triangle and the exact world point where the pixel's ray meets it. The light views' rasterizer
// is reused on the camera's projection, after clipping triangles at the camera's near plane.
#include <cstdint>
#include <vector>

#include "scene/camera.h"
#include "scene/scene.h"
#include "util/eigen.h"

namespace mb {

// The surfaces a pixel shows, nearest first: the nearest one, and in a scene with translucent parts
// (docs/reference.md §7) every surface behind it up to the first opaque one, which a compositor
// blends front to back. None: background.
struct CameraImage {
  int width = 0, height = 0;
  std::vector<uint64_t> offsets;   // pixel p's surfaces are [offsets[p], offsets[p + 1])
  std::vector<uint32_t> triangle;  // per surface: the scene triangle
  std::vector<Eigen::Vector3d>
      point;                  // per surface: the world point where the pixel's ray meets it
  std::vector<double> alpha;  // per surface: its opacity (1 where the scene is opaque)
};

CameraImage render_camera(const Scene& scene, const CameraDesc& camera, int threads);

}  // namespace mb
