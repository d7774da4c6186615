// The rasterizer on analytic geometry: exact coverage, exact depths, watertight shared edges.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/rasterizer.h"
#include "scene/procedural.h"

namespace mb {
namespace {

using Eigen::Vector3d;

// z = 0.2 + 0.0031 x + 0.0017 y, a sloped plane in raster space.
double plane_depth(double x, double y) {
  return 0.2 + 0.0031 * x + 0.0017 * y;
}

TEST(Rasterizer, PlaneGivesOneFragmentPerCoveredTexelWithAnalyticDepthAndGradient) {
  RasterInput in;
  in.width = 96;
  in.height = 80;
  // A convex quad whose corners lie off the texel-centre lattice, so no centre is on its boundary.
  Vector3d corners[4] = {
      {5.137, 7.291, 0}, {88.613, 3.377, 0}, {91.251, 70.719, 0}, {2.903, 76.433, 0}};
  for (auto& c : corners) c.z() = plane_depth(c.x(), c.y());
  in.vertices.assign(corners, corners + 4);
  in.triangles = {{0, 1, 2}, {0, 2, 3}};
  in.facing = {1, 1};
  LayerStack stack = rasterize(in, 1);

  auto inside = [&](double x, double y) {
    for (int k = 0; k < 4; ++k) {
      const Vector3d &a = corners[k], &b = corners[(k + 1) % 4];
      if ((b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x()) <= 0) return false;
    }
    return true;
  };
  size_t covered = 0;
  for (int row = 0; row < in.height; ++row) {
    for (int col = 0; col < in.width; ++col) {
      size_t t = size_t(row) * in.width + col;
      double x = col + 0.5, y = row + 0.5;
      ASSERT_EQ(stack.layers(t), inside(x, y) ? 1 : 0) << "texel " << col << "," << row;
      if (!inside(x, y)) continue;
      ++covered;
      size_t f = stack.offsets[t];
      EXPECT_NEAR(stack.depth[f], plane_depth(x, y), 1e-9);
      EXPECT_NEAR(stack.dz_dx[f], 0.0031, 1e-12);
      EXPECT_NEAR(stack.dz_dy[f], 0.0017, 1e-12);
      EXPECT_EQ(stack.facing[f], 1);
    }
  }
  EXPECT_GT(covered, 5000u);
}

TEST(Rasterizer, TessellatedPlaneCoversEveryTexelExactlyOnce) {
  // A plane larger than the map, cut into a jittered grid of triangles whose vertices often land
  // exactly on texel centres and texel-centre rows: every centre is on some edge or vertex tie.
  RasterInput in;
  in.width = in.height = 64;
  const int cells = 19;
  SeededRandom random(42);
  auto coordinate = [&](int i) { return -2.0 + 68.0 * i / cells; };
  for (int i = 0; i <= cells; ++i) {
    for (int k = 0; k <= cells; ++k) {
      double x = coordinate(i), y = coordinate(k);
      bool interior = i > 0 && i < cells && k > 0 && k < cells;
      if (interior) {
        // Half the interior vertices snap to a texel centre, the others are jittered.
        if (random.uniform() < 0.5) {
          x = std::floor(x) + 0.5, y = std::floor(y) + 0.5;
        } else {
          x += random.uniform(-1, 1), y += random.uniform(-1, 1);
        }
      }
      in.vertices.emplace_back(x, y, 0.5);
    }
  }
  auto index = [&](int i, int k) { return uint32_t(i * (cells + 1) + k); };
  for (int i = 0; i < cells; ++i) {
    for (int k = 0; k < cells; ++k) {
      // Alternate the diagonal so both orientations of shared edges occur.
      if ((i + k) % 2) {
        in.triangles.push_back({index(i, k), index(i + 1, k), index(i + 1, k + 1)});
        in.triangles.push_back({index(i, k), index(i + 1, k + 1), index(i, k + 1)});
      } else {
        in.triangles.push_back({index(i, k), index(i + 1, k), index(i, k + 1)});
        in.triangles.push_back({index(i + 1, k), index(i + 1, k + 1), index(i, k + 1)});
      }
    }
  }
  in.facing.assign(in.triangles.size(), 1);
  LayerStack stack = rasterize(in, 2);
  for (size_t t = 0; t < stack.texel_count(); ++t) ASSERT_EQ(stack.layers(t), 1) << "texel " << t;
}

TEST(Rasterizer, FanAroundAVertexOnATexelCentreCoversItOnce) {
  RasterInput in;
  in.width = in.height = 16;
  in.vertices.emplace_back(8.5, 8.5, 0.5);  // exactly a texel centre
  const int spokes = 7;
  for (int s = 0; s < spokes; ++s) {
    double angle = 2 * M_PI * s / spokes + 0.3;
    in.vertices.emplace_back(8.5 + 6 * std::cos(angle), 8.5 + 6 * std::sin(angle), 0.5);
  }
  for (int s = 0; s < spokes; ++s)
    in.triangles.push_back({0, uint32_t(1 + s), uint32_t(1 + (s + 1) % spokes)});
  in.facing.assign(spokes, 1);
  LayerStack stack = rasterize(in, 1);
  EXPECT_EQ(stack.layers(8 * 16 + 8), 1);
}

TEST(Rasterizer, OutputDoesNotDependOnThreadCount) {
  RasterInput in;
  in.width = in.height = 128;
  TriangleMesh mesh = make_sphere(40, {64, 64, 100}, 20, 40);
  for (const auto& v : mesh.vertices) in.vertices.emplace_back(v.x(), v.y(), v.z() / 200);
  in.triangles = mesh.triangles;
  for (size_t t = 0; t < in.triangles.size(); ++t) in.facing.push_back(t % 2);
  LayerStack one = rasterize(in, 1), two = rasterize(in, 2);
  EXPECT_GT(one.fragment_count(), 1000u);
  EXPECT_TRUE(one.same_fragments(two));
}

}  // namespace
}  // namespace mb
