#pragma once
// The scale of a false-colour picture: a ramp with its end values and its units, appended under
// the image so that the picture states what its colours mean. The image's own pixels are kept as
// they are (the first `height` rows of the result); the bar only adds rows beneath them.
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace mb {

struct ColourBar {
  std::function<std::array<float, 3>(double)> ramp;  // t in [0, 1] -> RGB in [0, 1]
  std::string low, middle, high;                     // values at t = 0, 0.5 (may be empty), 1
  std::string units;                                 // what the values are, under the ramp
  std::string quarter, three_quarters;               // values at t = 0.25, 0.75 (may be empty)
};

// The viridis bar of an error magnitude in [0, scale] (util/image_writer.h, colormap).
ColourBar magnitude_bar(double scale, const std::string& units);
// The blue-grey-red bar of a signed difference in [-scale, scale]: blue where a technique is
// lighter than the reference (light leaking), red where darker (over-darkening), each blended
// over the grey the difference images show the reference in (report/camera_images.h).
ColourBar signed_difference_bar(double scale, const std::array<float, 3>& lighter,
                                const std::array<float, 3>& darker, const std::string& units);

// The bar's text size in pixels for a picture `width` pixels wide: 11 up to 704 pixels, then
// growing with the picture (a sheet of 1092 pixels gets 17) up to 20, so that the scale stays
// readable where the picture is shown scaled to a page.
int colour_bar_font(int width);
// Rows the bar adds under an image `width` pixels wide (44 at the 11-pixel font).
int colour_bar_height(int width);
// `rgb` (width x height, 3 channels, row-major) on white with the bar beneath it, across
// max(320, 60 % of width) pixels from the left (at most the width), ticks and labels at 0, 1/4,
// 1/2, 3/4 and 1 of the ramp; an image too narrow for the bar's text is widened on the right
// (white). Labels need a font (DejaVuSans); without one the ramp stays and the scale is in the
// report.
struct BarredImage {
  std::vector<float> rgb;
  int width = 0, height = 0;
};
BarredImage with_colour_bar(const std::vector<float>& rgb, int width, int height,
                            const ColourBar& bar);

// write_image of with_colour_bar (PNG).
void write_with_colour_bar(const std::string& file, const std::vector<float>& rgb, int width,
                           int height, const ColourBar& bar);

}  // namespace mb
