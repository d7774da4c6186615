#pragma once
// Preview images of a LayerStack: layer-0 depth (16-bit grey, far plane white) and the number of
// layers per texel as a false-colour heat map (0 .. the view's maximum).
#include <string>

#include "raster/layer_stack.h"

namespace mb {

void write_depth_preview(const LayerStack& stack, const std::string& png_file);
void write_layer_count_preview(const LayerStack& stack, const std::string& png_file);

}  // namespace mb
