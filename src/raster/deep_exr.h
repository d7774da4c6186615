#pragma once
// LayerStack <-> deep OpenEXR (through OpenImageIO), readable by `oiiotool --info`.
// Channels per sample: Z (float depth, for viewers), facing (uint), and the exact doubles of
// depth and gradient as pairs of uint halves (depth_hi/lo, dzdx_hi/lo, dzdy_hi/lo), because deep
// EXR has no 64-bit float type and the round trip must be exact.
#include <string>

#include "raster/layer_stack.h"

namespace mb {

void write_deep_exr(const LayerStack& stack, const std::string& file);
LayerStack read_deep_exr(const std::string& file);

}  // namespace mb
