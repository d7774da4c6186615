#pragma once
// Flat images to PNG/EXR through OpenImageIO, and a perceptually ordered colour ramp for
// false-colour previews.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

// `values` row-major, `channels` per pixel, in [0, 1]; PNG gets 8 bits (16 with `sixteen_bit`),
// EXR gets float.
void write_image(const std::string& file, int width, int height, int channels,
                 const std::vector<float>& values, bool sixteen_bit = false);

// A viridis-like ramp: t in [0, 1] -> RGB in [0, 1] (piecewise linear through 9 stops).
std::array<float, 3> colormap(double t);

}  // namespace mb
