#pragma once
// LayerStack <-> deep OpenEXR (through OpenImageIO), readable by `oiiotool --info`.
// Channels per sample: Z (float depth, for viewers), facing (uint), and the exact doubles of
// depth and gradient as pairs of uint halves (depth_hi/lo, dzdx_hi/lo, dzdy_hi/lo), because deep
// EXR has no 64-bit float type and the round trip must be exact.
#include <bit>
#include <cstdint>
#include <string>

#include "raster/layer_stack.h"

namespace mb {

// Deep EXR has no 64-bit float type: a double kept exactly as two uint channels (this stack's and
// the transparency frames', oit/deep_frame_exr.h).
inline void split_double(double value, uint32_t& hi, uint32_t& lo) {
  const uint64_t bits = std::bit_cast<uint64_t>(value);
  hi = uint32_t(bits >> 32);
  lo = uint32_t(bits);
}
inline double join_double(uint32_t hi, uint32_t lo) {
  return std::bit_cast<double>((uint64_t(hi) << 32) | lo);
}

void write_deep_exr(const LayerStack& stack, const std::string& file);
LayerStack read_deep_exr(const std::string& file);

}  // namespace mb
