// PCF on an analytic scene: a square occluder plane above a ground plane, light straight down.
// Every ground fragment's PCF must equal the sum of normalised Gaussian weights over the taps whose
// texel centres lie under the occluder, computed here independently of the kernel code.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/render_view.h"
#include "scene/light_view.h"
#include "scene/procedural.h"
#include "shadow/fragments.h"
#include "util/error.h"

namespace mb {
namespace {

TEST(Pcf, PenumbraOfASquareOccluderEqualsTheSumOfGaussianWeights) {
  Scene scene;
  scene.name = "occluder";
  scene.mesh = make_ground_plane(8, 4);
  TriangleMesh occluder = make_ground_plane(2.3, 1);
  for (auto& v : occluder.vertices) v.y() += 1.0;
  scene.mesh.append(occluder);
  scene.two_sided.assign(scene.mesh.triangles.size(), 0);
  scene.views.push_back({"down", 0, 90, 64, 0.05});
  LayerStack stack = render_view(scene, scene.views[0], 2);
  LightFrame frame(scene.views[0], scene.mesh.vertices);
  // The occluder's raster rectangle.
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (double sx : {-1.15, 1.15})
    for (double sz : {-1.15, 1.15}) {
      Eigen::Vector3d r = frame.to_raster({sx, 1.0, sz});
      x0 = std::min(x0, r.x()), x1 = std::max(x1, r.x()), y0 = std::min(y0, r.y()),
      y1 = std::max(y1, r.y());
    }
  const int size = 9;
  const double sigma = 2.4;
  GaussianKernel kernel = make_gaussian_kernel(size, sigma);
  Fragments f = collect_receivers(stack, kernel, BiasParams{Reference::ReceiverPlane}, 2);
  double norm = 0;
  for (int d = -4; d <= 4; ++d) norm += std::exp(-d * d / (2 * sigma * sigma));
  int checked = 0, penumbra = 0;
  for (size_t k = 0; k < f.size(); ++k) {
    const int x = int(f.texel[k] % f.width), y = int(f.texel[k] / f.width);
    if (f.zf[k] < 0.5 || x < 4 || y < 4 || x >= f.width - 4 || y >= f.height - 4)
      continue;  // ground, inside
    double expected = 0;
    uint32_t covered = 0;  // taps under the occluder: ShadowRegion's count
    bool ambiguous = false;
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        double cx = x + dx + 0.5, cy = y + dy + 0.5;
        if (std::min({std::abs(cx - x0), std::abs(cx - x1), std::abs(cy - y0), std::abs(cy - y1)}) <
            1e-6)
          ambiguous = true;
        if (cx > x0 && cx < x1 && cy > y0 && cy < y1) {
          expected += std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)) / (norm * norm);
          ++covered;
        }
      }
    if (ambiguous) continue;
    ASSERT_NEAR(f.pcf[k], expected, 1e-12) << "texel " << x << "," << y;
    ASSERT_EQ(f.covered_taps[k], covered) << "texel " << x << "," << y;
    const ShadowRegion region = covered == 0    ? ShadowRegion::Unshadowed
                                : covered == 81 ? ShadowRegion::Interior
                                                : ShadowRegion::Silhouette;
    ASSERT_EQ(shadow_region(f, k), region);
    ++checked;
    if (expected > 0.01 && expected < 0.99) ++penumbra;
  }
  EXPECT_GT(checked, 2000);
  EXPECT_GT(penumbra, 100);  // the profile really crosses the penumbra
}

TEST(Pcf, KernelRejectsEvenZeroAndNonPositiveSigma) {
  EXPECT_THROW(make_gaussian_kernel(8, 2.4), InputError);
  EXPECT_THROW(make_gaussian_kernel(0, 2.4), InputError);
  EXPECT_THROW(make_gaussian_kernel(9, 0), InputError);
  GaussianKernel k = make_gaussian_kernel(9, 2.4);
  double total = 0;
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx) total += k.weight(dx, dy);
  EXPECT_NEAR(total, 1.0, 1e-15);
}

}  // namespace
}  // namespace mb
