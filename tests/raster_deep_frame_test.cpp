// A camera's deep frame (raster/deep_frame.h): two coloured panes over a coloured ground, seen and
// lit from above, so that every number of the centre pixel is known by hand.
#include <gtest/gtest.h>

#include "oit/deep_frame_exr.h"
#include "raster/deep_frame.h"
#include "scene/scene.h"
#include "shadow/compositing.h"
#include "test_support.h"
#include "util/error.h"

namespace mb {
namespace {

Scene panes() {
  return build_scene(parse_scene(testing_support::write_temp_file("panes.yaml", R"(name: panes
parts:
  - ground_plane: {size: 8}
    color: [0.2, 0.4, 0.6]
  - ground_plane: {size: 2}
    opacity: 0.5
    color: [1, 0, 0]
    transform: {translate: [0, 1.5, 0]}
  - ground_plane: {size: 2}
    opacity: 0.3
    color: [0, 1, 0]
    transform: {translate: [0, 2.5, 0]}
views:
  - {name: top, azimuth: 0, elevation: 90, resolution: 32}
cameras:
  - {name: above, position: [0, 10, 0.01], target: [0, 0, 0], fov: 40, resolution: [33, 33]}
)")));
}

TEST(DeepFrame, PanesOverGroundAreTheirDepthsOpacitiesAndColours) {
  const Scene scene = panes();
  const DeepFrame frame = render_deep_frame(scene, scene.cameras[0], 2);
  ASSERT_EQ(frame.pixels(), 33u * 33u);
  const size_t centre = 16 * 33 + 16;
  const PixelFragments px = pixel_of(frame, centre);
  ASSERT_EQ(px.size(), 2u);
  // Submission order is the scene's: the lower pane (part 1) first, though it is farther.
  EXPECT_DOUBLE_EQ(px.alpha[0], 0.5);
  EXPECT_DOUBLE_EQ(px.alpha[1], 0.3);
  EXPECT_NEAR(px.depth[0], 8.5, 1e-3);
  EXPECT_NEAR(px.depth[1], 7.5, 1e-3);
  // Lit from straight above, facing up: ambient + (1 - ambient) * 1 = 1, the albedo itself.
  EXPECT_NEAR(px.color[0][0], 1.0, 1e-5);
  EXPECT_NEAR(px.color[1][1], 1.0, 1e-5);
  EXPECT_NEAR(px.behind[2], 0.6, 1e-5);
  std::vector<double> t(2);
  exact_transmittance(px, t);
  EXPECT_DOUBLE_EQ(t[0], 0.7);
  EXPECT_DOUBLE_EQ(t[1], 1.0);
  const Rgb c = composite(px, t, total_transmittance(px));
  EXPECT_NEAR(c[0], 0.5 * 0.7 + 0.35 * 0.2, 1e-6);
  EXPECT_NEAR(c[1], 0.3 + 0.35 * 0.4, 1e-6);
  EXPECT_NEAR(c[2], 0.35 * 0.6, 1e-6);
  // A corner pixel sees only the ground; the nearest and farthest fragment are the panes'.
  EXPECT_EQ(pixel_of(frame, 0).size(), 0u);
  EXPECT_NEAR(frame.nearest(), 7.5, 0.05);
  EXPECT_NEAR(frame.farthest(), 8.5, 0.05);
  // The ground behind lies 10 units below the camera; a pixel beyond it shows the background.
  EXPECT_NEAR(frame.behind_depth[centre], 10, 1e-3);
}

// Deep OpenEXR round trip: depths, opacities and the surface behind come back bit for bit, colours
// to float rounding of the premultiplication; the composite from the file is the frame's.
TEST(DeepFrame, DeepExrRoundTrip) {
  const Scene scene = panes();
  const DeepFrame frame = render_deep_frame(scene, scene.cameras[0], 2);
  const std::string file = testing_support::write_temp_file("panes_frame.exr", "");
  write_deep_frame_exr(frame, scene.name, file);
  const DeepFrame back = read_deep_frame_exr(file);
  EXPECT_EQ(back.camera, "above");
  ASSERT_EQ(back.width, frame.width);
  ASSERT_EQ(back.offsets, frame.offsets);
  EXPECT_EQ(back.depth, frame.depth);
  EXPECT_EQ(back.alpha, frame.alpha);
  EXPECT_EQ(back.behind_depth, frame.behind_depth);
  for (size_t f = 0; f < frame.fragments(); ++f)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.color[f][c], frame.color[f][c], 1e-6) << f;
  for (size_t p = 0; p < frame.pixels(); ++p)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(back.behind[p][c], frame.behind[p][c]) << p;
  EXPECT_THROW(read_deep_frame_exr(testing_support::write_temp_file("not.exr", "no")), InputError);
}

}  // namespace
}  // namespace mb
