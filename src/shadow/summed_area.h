#pragma once
// Summed-area tables of per-texel moments (docs/soft-shadows.md §2; seed 001 "SAVSM", seed 004
// §3.2): the mean of any axis-aligned rectangle of the map from a few table entries, so a filter of
// any size costs the same. Values lie in [0, 1] and are stored as integers: `Fixed32` is seed 004's
// format, each value times floor((2^32 - 1) / N) rounded, summed modulo 2^32, which any box of at
// most N texels recovers exactly; `Exact` sums 128-bit integers of 2^53 times the value (no wrap
// on any map), so a box's sum is the direct sum of its texels' integers, bit for bit.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mb {

enum class SatPrecision { Fixed32, Exact };

class SummedAreaTable {
 public:
  // `values` holds `channels` numbers per texel of a width x height map, row-major; texels outside
  // the map read `outside` (the far plane's values) up to `pad` texels beyond every edge. `max_box`
  // is N, the most texels one box query may span (Fixed32's scale).
  SummedAreaTable(const std::vector<double>& values, int width, int height, int channels,
                  const std::vector<double>& outside, int pad, int64_t max_box,
                  SatPrecision precision);

  int channels() const { return channels_; }
  // The mean of every channel over the texels [x0, x1) x [y0, y1) (map coordinates, x1 > x0,
  // y1 > y0, at most N texels).
  void box_mean(int x0, int y0, int x1, int y1, double* mean) const;
  // The area-weighted mean over the real rectangle [ax, bx] x [ay, by], texel (i, j) covering
  // [i, i + 1) x [j, j + 1): the boxes of its whole texels, border strips and corners (seed 004's
  // nine regions), each recovered as integers and weighted by its share of the rectangle.
  void rect_mean(double ax, double ay, double bx, double by, double* mean) const;
  // The stored integer of one texel's channel, as a value (what a direct sum adds).
  double stored(int x, int y, int channel) const;
  double scale() const { return scale_; }

 private:
  // Sum of channel c's integers over [x0, x1) x [y0, y1), in table coordinates, as a double.
  double box_sum(int x0, int y0, int x1, int y1, int c) const;
  size_t at(int x, int y) const { return (size_t(y) * (width_ + 1) + x) * channels_; }
  int width_, height_, channels_, pad_;
  SatPrecision precision_;
  double scale_;
  std::vector<uint32_t> fixed_;          // Fixed32: (width + 1) x (height + 1) prefix sums
  std::vector<unsigned __int128> wide_;  // Exact
};

}  // namespace mb
