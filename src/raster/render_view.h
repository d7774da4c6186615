#pragma once
// One light view of a scene -> its LayerStack: the fitted orthographic projection (scene/), then
// the rasterizer. Facing comes from the world-space normal: n . to_light > 0, or two-sided.
#include <string>

#include "raster/layer_stack.h"
#include "scene/scene.h"

namespace mb {

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads);

// Refuses (InputError with both figures) a resolution whose layer stack cannot fit in the memory
// this process may use (the smallest of MemAvailable, the cgroup's limit and RLIMIT_AS): checked
// before rendering, since running out inside the rasterizer's threads aborts.
void check_render_memory(int resolution, const std::string& where);

}  // namespace mb
