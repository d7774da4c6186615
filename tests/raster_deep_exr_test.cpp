// Deep EXR is the LayerStack's file format: the round trip must be bit-exact.
#include <gtest/gtest.h>

#include <filesystem>

#include "raster/deep_exr.h"
#include "raster/render_view.h"
#include "scene/dataset.h"
#include "util/error.h"

namespace mb {
namespace {

Scene tiny_scene(int index) {
  DatasetDesc dataset = load_dataset("tiny");
  return build_scene(parse_scene(dataset.scene_files.at(index)));
}

TEST(DeepExr, WriteThenReadIsExact) {
  Scene scene = tiny_scene(0);
  LayerStack stack = render_view(scene, scene.views[0], 2);
  ASSERT_GT(stack.fragment_count(), 1000u);
  auto file = std::filesystem::temp_directory_path() / "momentbench_roundtrip.exr";
  write_deep_exr(stack, file.string());
  LayerStack back = read_deep_exr(file.string());
  std::filesystem::remove(file);
  EXPECT_TRUE(stack.same_fragments(back));
  EXPECT_EQ(back.scene, stack.scene);
  EXPECT_EQ(back.view, stack.view);
  EXPECT_EQ(back.frame, stack.frame);
}

TEST(DeepExr, RejectsAFileThatIsNotALayerStack) {
  EXPECT_THROW(read_deep_exr("/nonexistent/stack.exr"), InputError);
}

TEST(RenderView, OneAndTwoThreadsGiveIdenticalStacksForEveryTinyView) {
  for (int s = 0; s < 2; ++s) {
    Scene scene = tiny_scene(s);
    for (const auto& view : scene.views) {
      LayerStack one = render_view(scene, view, 1), two = render_view(scene, view, 2);
      EXPECT_TRUE(one.same_fragments(two)) << scene.name << "/" << view.name;
    }
  }
}

}  // namespace
}  // namespace mb
