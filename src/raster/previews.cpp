#include "raster/previews.h"

#include <algorithm>

#include "util/image_writer.h"

namespace mb {

void write_depth_preview(const LayerStack& stack, const std::string& png_file) {
  std::vector<float> pixels(stack.texel_count());
  for (size_t t = 0; t < pixels.size(); ++t) pixels[t] = float(stack.layer0_depth(t));
  write_image(png_file, stack.width, stack.height, 1, pixels, true);
}

void write_layer_count_preview(const LayerStack& stack, const std::string& png_file) {
  int max_layers = 1;
  for (size_t t = 0; t < stack.texel_count(); ++t)
    max_layers = std::max(max_layers, stack.layers(t));
  std::vector<float> pixels(stack.texel_count() * 3);
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    auto rgb = colormap(double(stack.layers(t)) / max_layers);
    std::copy(rgb.begin(), rgb.end(), pixels.begin() + 3 * t);
  }
  write_image(png_file, stack.width, stack.height, 3, pixels);
}

}  // namespace mb
