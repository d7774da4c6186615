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

struct CameraImage {
  int width = 0, height = 0;
  std::vector<int64_t> triangle;       // per pixel: the scene triangle seen, -1 for background
  std::vector<Eigen::Vector3d> point;  // per pixel: the world point seen (where triangle >= 0)
};

CameraImage render_camera(const Scene& scene, const CameraDesc& camera, int threads);

}  // namespace mb
