#pragma once
// One light view of a scene -> its LayerStack: the fitted orthographic projection (scene/), then
// the rasterizer. Facing comes from the world-space normal: n . to_light > 0, or two-sided.
#include "raster/layer_stack.h"
#include "scene/scene.h"

namespace mb {

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads);

}  // namespace mb
