// `render`'s run as a library unit (raster/render_dataset.h): the scenes' views at the resolution
// asked for, every view handed on once in order with its stack's own statistics, and a dataset
// that rasterizes nothing refused with its file named.
#include <gtest/gtest.h>

#include "raster/render_dataset.h"
#include "raster/render_view.h"
#include "test_support.h"

namespace mb {
namespace {

TEST(RenderDataset, ViewsTakeTheResolutionAskedForElseTheDatasets) {
  const DatasetDesc tiny = load_dataset("tiny");
  ASSERT_GT(tiny.resolution, 0);
  for (const auto& [asked, expected] : {std::pair{0, tiny.resolution}, std::pair{24, 24}}) {
    const std::vector<Scene> scenes = build_render_scenes(tiny, asked);
    ASSERT_EQ(scenes.size(), tiny.scene_files.size());
    for (const auto& scene : scenes) {
      ASSERT_FALSE(scene.views.empty()) << scene.name;
      for (const auto& view : scene.views) EXPECT_EQ(view.resolution, expected) << view.name;
    }
  }
  // Neither asked for nor the dataset's: each view keeps its scene file's.
  DatasetDesc own = tiny;
  own.resolution = 0;
  const std::vector<Scene> scenes = build_render_scenes(own, 0);
  for (size_t s = 0; s < scenes.size(); ++s) {
    const Scene parsed = build_scene(parse_scene(tiny.scene_files[s]));
    for (size_t v = 0; v < scenes[s].views.size(); ++v)
      EXPECT_EQ(scenes[s].views[v].resolution, parsed.views[v].resolution);
  }
}

TEST(RenderDataset, EveryViewOnceInOrderWithItsStacksStatistics) {
  const DatasetDesc tiny = load_dataset("tiny");
  const std::vector<Scene> scenes = build_render_scenes(tiny, 32);
  std::vector<std::string> seen;
  render_views(scenes, tiny, 2, [&](const RenderedView& r) {
    seen.push_back(r.scene.name + "/" + r.view.name);
    EXPECT_EQ(r.stack.width, 32);
    EXPECT_GE(r.seconds, 0);
    const LayerStackStats direct =
        compute_stats(render_view(r.scene, r.view, 1), r.scene.mesh.triangles.size());
    EXPECT_EQ(r.stats.fragments, direct.fragments) << seen.back();
    EXPECT_EQ(r.stats.receivers, direct.receivers) << seen.back();
    EXPECT_EQ(r.stats.triangles, r.scene.mesh.triangles.size());
  });
  std::vector<std::string> expected;
  for (const auto& scene : scenes)
    for (const auto& view : scene.views) expected.push_back(scene.name + "/" + view.name);
  EXPECT_EQ(seen, expected);
}

TEST(RenderDataset, NothingRasterizedIsAnErrorNamingTheDataset) {
  const DatasetDesc degenerate = load_dataset(MOMENTBENCH_TEST_DATA "/bad/dataset_degenerate.yaml");
  const std::vector<Scene> scenes = build_render_scenes(degenerate, 16);
  size_t handed = 0;
  const std::string message = testing_support::input_error_of(
      [&] { render_views(scenes, degenerate, 1, [&](const RenderedView&) { ++handed; }); });
  EXPECT_NE(message.find("dataset_degenerate.yaml: dataset " + degenerate.name +
                         " has nothing to render"),
            std::string::npos)
      << message;
  EXPECT_GT(handed, 0u);  // every view was rendered before the verdict
}

}  // namespace
}  // namespace mb
