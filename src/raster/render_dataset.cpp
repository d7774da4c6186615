#include "raster/render_dataset.h"

#include <chrono>

#include "raster/render_view.h"
#include "util/error.h"

namespace mb {

std::vector<Scene> build_render_scenes(const DatasetDesc& dataset, int resolution) {
  if (resolution == 0) resolution = dataset.resolution;
  std::vector<Scene> scenes;
  for (const auto& file : dataset.scene_files) {
    scenes.push_back(build_scene(parse_scene(file)));
    if (resolution > 0)
      for (auto& view : scenes.back().views) view.resolution = resolution;
  }
  return scenes;
}

void render_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset, int threads,
                  const std::function<void(const RenderedView&)>& each) {
  size_t fragments = 0;
  for (const auto& scene : scenes)
    for (const auto& view : scene.views) {
      const auto start = std::chrono::steady_clock::now();
      const LayerStack stack = render_view(scene, view, threads);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const RenderedView rendered{scene, view, stack,
                                  compute_stats(stack, scene.mesh.triangles.size()), seconds};
      fragments += rendered.stats.fragments;
      each(rendered);
    }
  if (fragments == 0)
    throw InputError(dataset.file + ": dataset " + dataset.name +
                     " has nothing to render: no view of any scene rasterizes a fragment (every "
                     "triangle degenerate, or no geometry inside the views)");
}

}  // namespace mb
