// The colour bar under a false-colour picture (report/colour_bar.h): the picture's own pixels stay
// as they were, the ramp beneath runs from the scale's low colour to its high one, and a picture
// too narrow for the bar's text is widened on the right.
#include <gtest/gtest.h>

#include <vector>

#include "report/colour_bar.h"
#include "util/image_writer.h"

namespace mb {
namespace {

float at(const BarredImage& image, int x, int y, int channel) {
  return image.rgb[(size_t(y) * image.width + x) * 3 + channel];
}

TEST(ColourBar, KeepsThePicturesPixelsAndAddsTheRampBeneath) {
  const int w = 400, h = 30;
  std::vector<float> rgb(size_t(w) * h * 3);
  for (size_t k = 0; k < rgb.size(); ++k) rgb[k] = float(k % 97) / 97;
  const BarredImage barred = with_colour_bar(rgb, w, h, magnitude_bar(10, "CIEDE2000"));
  ASSERT_EQ(barred.width, w);
  ASSERT_EQ(barred.height, h + colour_bar_height(w));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(at(barred, x, y, c), rgb[(size_t(y) * w + x) * 3 + c]) << x << "," << y;
  // The ramp's ends, in its middle row: viridis at 0 and at 1 (8-bit PNG aside, exact here).
  const int row = h + 8;
  const auto low = colormap(0), high = colormap(1);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(at(barred, 4, row, c), low[c]);
    EXPECT_FLOAT_EQ(at(barred, 4 + 312 - 1, row, c), high[c]);
  }
  // Labels are drawn in black below the ramp somewhere (a font is installed: fonts-dejavu-core).
  bool dark = false;
  for (int y = h + 14; y < barred.height; ++y)
    for (int x = 0; x < w; ++x) dark |= at(barred, x, y, 0) < 0.5f;
  EXPECT_TRUE(dark);
}

// A wide picture (a contact sheet) gets a bar across 60 % of it and a larger font, and the ramp
// is labelled at its quarters too.
TEST(ColourBar, ScalesWithTheWidthOfThePicture) {
  EXPECT_EQ(colour_bar_font(400), 11);
  EXPECT_GT(colour_bar_font(1092), 11);
  EXPECT_LE(colour_bar_font(100000), 20);
  EXPECT_GT(colour_bar_height(1092), colour_bar_height(400));
  const int w = 1092, h = 8;
  const std::vector<float> rgb(size_t(w) * h * 3, 1.0f);
  const BarredImage barred = with_colour_bar(rgb, w, h, magnitude_bar(10, "CIEDE2000"));
  const int row = h + 3 + colour_bar_font(w) / 2, last = 4 + w * 3 / 5 - 8 - 1;
  const auto high = colormap(1);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(at(barred, last, row, c), high[c]);
  const ColourBar bar = magnitude_bar(10, "CIEDE2000");
  EXPECT_EQ(bar.quarter, "2.5");
  EXPECT_EQ(bar.middle, "5");
  EXPECT_EQ(bar.three_quarters, "7.5");
  EXPECT_EQ(signed_difference_bar(0.5, {0, 0, 1}, {1, 0, 0}, "").quarter, "-0.25");
}

TEST(ColourBar, SignedDifferenceRunsFromLighterThroughGreyToDarker) {
  const std::array<float, 3> blue = {0, 0, 1}, red = {1, 0, 0};
  const ColourBar bar = signed_difference_bar(0.5, blue, red, "G - PCF");
  EXPECT_EQ(bar.ramp(0), blue);
  EXPECT_EQ(bar.ramp(1), red);
  const auto mid = bar.ramp(0.5);
  EXPECT_EQ(mid[0], mid[2]);  // neither colour at 0
  EXPECT_EQ(bar.low, "<= -0.5");
  EXPECT_EQ(bar.high, ">= 0.5");
}

TEST(ColourBar, ANarrowPictureIsWidenedForTheText) {
  const int w = 16, h = 16;
  const std::vector<float> rgb(size_t(w) * h * 3, 0.25f);
  const BarredImage barred =
      with_colour_bar(rgb, w, h, magnitude_bar(0.5, "|G - PCF|, shadow fraction"));
  EXPECT_GT(barred.width, w);
  for (int y = 0; y < h; ++y) {
    EXPECT_EQ(at(barred, w - 1, y, 0), 0.25f);
    EXPECT_EQ(at(barred, w, y, 0), 1.0f);  // white to the right of the picture
  }
}

}  // namespace
}  // namespace mb
