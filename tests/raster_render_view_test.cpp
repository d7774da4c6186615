// Closed solids through the whole path scene -> light frame -> rasterizer: exactly two layers
// inside the silhouette (one facing the light) at the analytic depths.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/render_view.h"
#include "scene/procedural.h"

namespace mb {
namespace {

using Eigen::Vector3d;

Scene single_mesh_scene(TriangleMesh mesh, double azimuth, double elevation, int resolution) {
  Scene scene;
  scene.name = "analytic";
  scene.two_sided.assign(mesh.triangles.size(), 0);
  scene.mesh = std::move(mesh);
  scene.views.push_back({"v", azimuth, elevation, resolution, 0.1});
  return scene;
}

TEST(RenderView, SphereSeenFromAboveHasTwoLayersAtAnalyticDepths) {
  const double radius = 1.0;
  const int segments = 64, rings = 32;
  Scene scene = single_mesh_scene(make_sphere(radius, {0, 0, 0}, rings, segments), 0, 90, 128);
  LayerStack stack = render_view(scene, scene.views[0], 2);
  LightFrame frame(scene.views[0], scene.mesh.vertices);
  Vector3d center = frame.to_raster(Vector3d::Zero());
  double texel = frame.world_per_texel();
  // The tessellation lies between the inner polygon and the sphere: chord sagitta bounds depths.
  double sagitta = radius * (1 - std::cos(M_PI / rings));
  int inside_texels = 0;
  for (int row = 0; row < stack.height; ++row) {
    for (int col = 0; col < stack.width; ++col) {
      size_t t = size_t(row) * stack.width + col;
      double d = std::hypot(col + 0.5 - center.x(), row + 0.5 - center.y()) * texel;
      double inner = radius * std::cos(M_PI / segments);  // the equator ring (rings is even)
      if (d < inner - texel) {
        ASSERT_EQ(stack.layers(t), 2) << col << "," << row;
        ++inside_texels;
        size_t f = stack.offsets[t];
        EXPECT_EQ(stack.facing[f], 1);
        EXPECT_EQ(stack.facing[f + 1], 0);
        double h = std::sqrt(radius * radius - d * d);
        double top = frame.to_raster(Vector3d(0, h, 0)).z(),
               bottom = frame.to_raster(Vector3d(0, -h, 0)).z();
        // Near the rim the surface is steep: allow the sagitta stretched by the slope.
        double slack = (sagitta + 2 * texel * d / h) / frame.world_per_depth();
        EXPECT_NEAR(stack.depth[f], top, slack);
        EXPECT_NEAR(stack.depth[f + 1], bottom, slack);
        EXPECT_GE(stack.depth[f], top - 1e-12);  // the polyhedron lies inside the sphere
      } else if (d > radius + texel) {
        ASSERT_EQ(stack.layers(t), 0);
      }
    }
  }
  EXPECT_GT(inside_texels, 3000);
}

TEST(RenderView, BoxHasTwoLayersInsideItsSilhouetteFromEveryDirection) {
  Scene scene = single_mesh_scene(make_box({1.3, 0.7, 0.9}, {0.1, 0.2, -0.3}), 0, 90, 96);
  // Straight down: the exact depths of the top and bottom faces.
  LayerStack stack = render_view(scene, scene.views[0], 1);
  LightFrame frame(scene.views[0], scene.mesh.vertices);
  double top = frame.to_raster(Vector3d(0, 0.2 + 0.35, 0)).z(),
         bottom = frame.to_raster(Vector3d(0, 0.2 - 0.35, 0)).z();
  size_t two_layer_texels = 0;
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    int n = stack.layers(t);
    ASSERT_TRUE(n == 0 || n == 2);
    if (n == 0) continue;
    ++two_layer_texels;
    EXPECT_NEAR(stack.depth[stack.offsets[t]], top, 1e-12);
    EXPECT_NEAR(stack.depth[stack.offsets[t] + 1], bottom, 1e-12);
    EXPECT_EQ(stack.facing[stack.offsets[t]] + stack.facing[stack.offsets[t] + 1], 1);
  }
  EXPECT_GT(two_layer_texels, 2000u);
  // Oblique views: the ray through any texel crosses a closed convex solid 0 or 2 times.
  for (auto [azimuth, elevation] : {std::pair{33.0, 41.0}, {200.0, 15.0}, {-75.0, 70.0}}) {
    scene.views[0].azimuth_deg = azimuth;
    scene.views[0].elevation_deg = elevation;
    LayerStack oblique = render_view(scene, scene.views[0], 2);
    size_t covered = 0;
    for (size_t t = 0; t < oblique.texel_count(); ++t) {
      int n = oblique.layers(t);
      ASSERT_TRUE(n == 0 || n == 2) << "azimuth " << azimuth << " texel " << t << " has " << n;
      if (n == 2) {
        ++covered;
        EXPECT_EQ(oblique.facing[oblique.offsets[t]], 1);
        EXPECT_EQ(oblique.facing[oblique.offsets[t] + 1], 0);
      }
    }
    EXPECT_GT(covered, 1000u);
  }
}

}  // namespace
}  // namespace mb
