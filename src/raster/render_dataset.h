#pragma once
// What `render` runs (docs/user-guide.md, render): a dataset's scenes, built before anything is
// written, and every light view of each rasterized into its layer stack and timed. The command
// writes the stacks, previews and statistics; this is reachable from tests.
#include <functional>
#include <string>
#include <vector>

#include "raster/layer_stack.h"
#include "scene/dataset.h"
#include "scene/scene.h"

namespace mb {

// The dataset's scenes, parsed and built (bad input fails here, before any output), every view at
// `resolution` when > 0, else at the dataset's when > 0, else at its own.
std::vector<Scene> build_render_scenes(const DatasetDesc& dataset, int resolution);

// One view as `render` hands it on: its layer stack, the stack's statistics and the wall clock of
// its rendering alone.
struct RenderedView {
  const Scene& scene;
  const LightViewDesc& view;
  const LayerStack& stack;
  LayerStackStats stats;
  double seconds;
};

// Renders every view of every scene, in order, and hands each to `each` (the stack lives until
// `each` returns). As eval and verify say of a dataset without receivers, nothing rendered is an
// error: InputError naming the dataset's file when no view rasterizes a fragment.
void render_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset, int threads,
                  const std::function<void(const RenderedView&)>& each);

}  // namespace mb
