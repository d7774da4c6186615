#pragma once
// DeepFrame <-> deep OpenEXR (through OpenImageIO), as compositors read deep images: per pixel
// its transparent fragments in submission order, then the opaque surface behind them (A = 1; Z
// infinite for the background). R, G, B are premultiplied by A (OpenEXR's deep convention); Z and
// A are floats for viewers, and depth and alpha are kept exactly as pairs of uint halves
// (depth_hi/lo, alpha_hi/lo), since deep EXR has no 64-bit float type. Colours come back to float
// rounding of the premultiplication.
#include <string>

#include "raster/deep_frame.h"

namespace mb {

void write_deep_frame_exr(const DeepFrame& frame, const std::string& scene,
                          const std::string& file);
// InputError naming the file and what is missing for a file that is not such a frame.
DeepFrame read_deep_frame_exr(const std::string& file);

}  // namespace mb
