// Camera views (issue 34, camera/camera_views.h): a camera looking straight down at a ground plane
// sees the shadow of a square held above it, displaced by the light's slant; the pixels PCF puts
// in shadow cover the square's area at the ground's pixel scale, centred where geometry says.
// Exact techniques stay below PCF on every camera receiver, and the light view's receivers and a
// camera's are one test: a camera pixel gets its light texel's G.
#include "camera/camera_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "eval/evaluation.h"
#include "report/camera_images.h"
#include "scene/procedural.h"

namespace mb {
namespace {

struct SquareScene {
  Scene scene;
  CameraDesc camera;
  double height = 1.5, side = 1;
  SquareScene() {
    scene.name = "square";
    scene.mesh = make_ground_plane(12, 8);
    TriangleMesh square = make_ground_plane(side, 1);
    for (auto& v : square.vertices) v += Eigen::Vector3d(0, height, 0);
    scene.mesh.append(square);
    scene.two_sided.assign(scene.mesh.triangles.size(), 0);
    // Light from +z at 45 degrees: the shadow lies `height` towards -z, beside the square.
    scene.views.push_back({"slant", 0, 45, 512, 0.02});
    camera.name = "down";
    camera.position = {0, 10, -height};
    camera.target = {0, 0, -height};
    camera.fov_deg = 40;
    camera.width = camera.height = 200;
  }
};

TEST(CameraViews, AFloatingSquaresShadowHasItsAreaAndPlace) {
  SquareScene s;
  EvalSettings settings;
  settings.threads = 2;
  const ViewData light = prepare_view(s.scene, s.scene.views[0], settings);
  const CameraView view = camera_view(s.scene, s.scene.views[0], light, s.camera, settings);
  ASSERT_EQ(view.width, 200);
  // One pixel's footprint on the ground, 10 units below the camera.
  const double pixel = 2 * 10 * std::tan(20 * std::numbers::pi / 180) / 200;
  const double expected = s.side * s.side / (pixel * pixel);
  const Fragments& f = view.receivers.fragments;
  double shadowed = 0, cx = 0, cy = 0;
  for (size_t k = 0; k < f.size(); ++k)
    if (f.pcf[k] >= 0.5) {
      ++shadowed;
      cx += view.pixel[k] % view.width + 0.5;
      cy += view.pixel[k] / view.width + 0.5;
    }
  // PCF's 0.5 contour of a square follows its edges and rounds its corners a little.
  EXPECT_NEAR(shadowed, expected, 0.03 * expected);
  EXPECT_NEAR(cx / shadowed, 100, 1.5);
  EXPECT_NEAR(cy / shadowed, 100, 1.5);
  // The ground (12 wide) fills the view: every pixel sees a surface.
  size_t seen = 0;
  for (float d : view.diffuse) seen += d >= 0;
  EXPECT_EQ(seen, view.diffuse.size());

  for (const char* name : {"pcf", "hamburger4", "hausdorff4", "vsm"}) {
    const TechniqueResult r = evaluate_technique(view.receivers, name, settings, nullptr);
    for (size_t k = 0; k < f.size(); ++k) ASSERT_LE(r.shadow[k], f.pcf[k] + 1e-9) << name;
  }
  // A camera pixel is its light texel's receiver of the same surface: the same z_f, z_f - delta_f
  // and PCF as the light view's fragment of that texel at that depth.
  size_t matched = 0;
  for (size_t k = 0, j = 0; k < f.size(); ++k) {
    while (j < light.fragments.size() && light.fragments.texel[j] < f.texel[k]) ++j;
    for (size_t i = j; i < light.fragments.size() && light.fragments.texel[i] == f.texel[k]; ++i)
      if (std::abs(light.fragments.zf[i] - f.zf[k]) < 1e-9) {
        EXPECT_NEAR(f.ztest[k], light.fragments.ztest[i], 1e-9);
        EXPECT_EQ(f.pcf[k], light.fragments.pcf[i]);  // one function computes both
        ++matched;
      }
  }
  EXPECT_GT(matched, f.size() / 2);
}

TEST(CameraViews, ImagesShadeThePcfShadowDarker) {
  SquareScene s;
  EvalSettings settings;
  const ViewData light = prepare_view(s.scene, s.scene.views[0], settings);
  const CameraView view = camera_view(s.scene, s.scene.views[0], light, s.camera, settings);
  const Fragments& f = view.receivers.fragments;
  const std::vector<float> lit = shade_camera_view(view, std::vector<double>(f.size(), 0.0));
  const std::vector<float> pcf = shade_camera_view(view, f.pcf);
  // The centre pixel is in the shadow: darker than unshadowed, as dark as ambient light allows.
  const size_t centre = 100 * 200 + 100;
  EXPECT_LT(pcf[centre * 3], 0.75f * lit[centre * 3]);
  // A difference image of PCF against itself is its grey backdrop only.
  const std::vector<float> same = difference_image(view, f.pcf, 0.5);
  for (size_t p = 0; p < same.size() / 3; ++p) {
    ASSERT_EQ(same[p * 3], same[p * 3 + 1]);
    ASSERT_EQ(same[p * 3 + 1], same[p * 3 + 2]);
  }
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// Under an area light a camera pixel is still its light texel's receiver: its reference is the
// area light's shadow computed for the light view's fragment of that texel at that depth, its
// hard test is kept for the pcf row, and the penumbra widens the shadow beyond the hard one.
TEST(CameraViews, AnAreaLightsShadowIsTheLightViewsAtTheSameTexel) {
  SquareScene s;
  EvalSettings settings;
  settings.threads = 2;
  settings.light.directions = 16;
  LightViewDesc slant = s.scene.views[0];
  slant.light_angle_deg = 6;
  const ViewData light = prepare_view(s.scene, slant, settings);
  const CameraView view = camera_view(s.scene, slant, light, s.camera, settings);
  const Fragments& f = view.receivers.fragments;
  ASSERT_EQ(view.receivers.soft.angle_deg, 6);
  ASSERT_EQ(view.receivers.soft.hard.size(), f.size());
  size_t matched = 0, penumbra = 0;
  for (size_t k = 0, j = 0; k < f.size(); ++k) {
    while (j < light.fragments.size() && light.fragments.texel[j] < f.texel[k]) ++j;
    for (size_t i = j; i < light.fragments.size() && light.fragments.texel[i] == f.texel[k]; ++i)
      if (std::abs(light.fragments.zf[i] - f.zf[k]) < 1e-9) {
        EXPECT_NEAR(f.pcf[k], light.fragments.pcf[i], 1e-6);
        EXPECT_EQ(view.receivers.soft.hard[k], light.soft.hard[i]);
        ++matched;
      }
    penumbra += f.pcf[k] > 0.02 && view.receivers.soft.hard[k] < 0.02;
  }
  EXPECT_GT(matched, f.size() / 2);
  EXPECT_GT(penumbra, 100u);  // lit by the hard light, partly shadowed by the area light
  // The soft techniques run on camera receivers as on the light view's.
  const TechniqueResult pcss = evaluate_technique(view.receivers, "pcss_exact", settings, nullptr);
  double soft = 0, hard = 0;
  for (size_t k = 0; k < f.size(); ++k) {
    soft += std::abs(pcss.shadow[k] - f.pcf[k]);
    hard += std::abs(view.receivers.soft.hard[k] - f.pcf[k]);
  }
  EXPECT_LT(soft, 0.5 * hard);
}

}  // namespace
}  // namespace mb
