#include "shadow/summed_area.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mb {

SummedAreaTable::SummedAreaTable(const std::vector<double>& values, int width, int height,
                                 int channels, const std::vector<double>& outside, int pad,
                                 int64_t max_box, SatPrecision precision)
    : width_(width + 2 * pad),
      height_(height + 2 * pad),
      channels_(channels),
      pad_(pad),
      precision_(precision) {
  if (max_box < 1 || max_box > (int64_t(1) << 32))
    throw std::invalid_argument("SummedAreaTable: max_box outside [1, 2^32]");
  scale_ = precision == SatPrecision::Fixed32 ? std::floor(4294967295.0 / double(max_box)) : 0x1p53;
  const size_t entries = size_t(width_ + 1) * (height_ + 1) * channels_;
  if (precision == SatPrecision::Fixed32)
    fixed_.assign(entries, 0);
  else
    wide_.assign(entries, 0);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      for (int c = 0; c < channels_; ++c) {
        const int mx = x - pad, my = y - pad;
        const bool inside = mx >= 0 && my >= 0 && mx < width && my < height;
        const double v = inside ? values[(size_t(my) * width + mx) * channels + c] : outside[c];
        const double q = std::nearbyint(std::clamp(v, 0.0, 1.0) * scale_);
        // S(x+1, y+1) = v + S(x, y+1) + S(x+1, y) - S(x, y), wrapping modulo 2^32 for Fixed32
        // (seed 004 §3.2: a box of at most N texels still comes out exact).
        const size_t s = at(x + 1, y + 1) + c, l = at(x, y + 1) + c, u = at(x + 1, y) + c,
                     d = at(x, y) + c;
        if (precision == SatPrecision::Fixed32)
          fixed_[s] = uint32_t(q) + fixed_[l] + fixed_[u] - fixed_[d];
        else
          wide_[s] = static_cast<unsigned __int128>(q) + wide_[l] + wide_[u] - wide_[d];
      }
}

double SummedAreaTable::box_sum(int x0, int y0, int x1, int y1, int c) const {
  if (precision_ == SatPrecision::Fixed32)
    return double(uint32_t(fixed_[at(x1, y1) + c] - fixed_[at(x0, y1) + c] -
                           fixed_[at(x1, y0) + c] + fixed_[at(x0, y0) + c]));
  return double(wide_[at(x1, y1) + c] - wide_[at(x0, y1) + c] - wide_[at(x1, y0) + c] +
                wide_[at(x0, y0) + c]);
}

double SummedAreaTable::stored(int x, int y, int channel) const {
  return box_sum(x + pad_, y + pad_, x + pad_ + 1, y + pad_ + 1, channel) / scale_;
}

void SummedAreaTable::box_mean(int x0, int y0, int x1, int y1, double* mean) const {
  const auto clampx = [&](int v) { return std::clamp(v + pad_, 0, width_); };
  const auto clampy = [&](int v) { return std::clamp(v + pad_, 0, height_); };
  const double area = double(x1 - x0) * double(y1 - y0);
  for (int c = 0; c < channels_; ++c)
    mean[c] = box_sum(clampx(x0), clampy(y0), clampx(x1), clampy(y1), c) / scale_ / area;
}

namespace {

// The pieces of [a, b] along one axis: whole texels [first, last) with their coverage weight.
struct Piece {
  int first, last;
  double weight;
};

int pieces_of(double a, double b, Piece* out) {
  const int fa = int(std::floor(a)), fb = int(std::floor(b));
  if (fa == fb || (fb == fa + 1 && b == fb)) {
    out[0] = {fa, fa + 1, b - a};
    return 1;
  }
  int n = 0;
  out[n++] = {fa, fa + 1, (fa + 1) - a};
  if (fb > fa + 1) out[n++] = {fa + 1, fb, 1.0};
  if (b > fb) out[n++] = {fb, fb + 1, b - fb};
  return n;
}

}  // namespace

void SummedAreaTable::rect_mean(double ax, double ay, double bx, double by, double* mean) const {
  Piece px[3], py[3];
  const int nx = pieces_of(ax, bx, px), ny = pieces_of(ay, by, py);
  const auto cx = [&](int v) { return std::clamp(v + pad_, 0, width_); };
  const auto cy = [&](int v) { return std::clamp(v + pad_, 0, height_); };
  const double area = (bx - ax) * (by - ay);
  for (int c = 0; c < channels_; ++c) {
    double sum = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        sum += px[i].weight * py[j].weight *
               box_sum(cx(px[i].first), cy(py[j].first), cx(px[i].last), cy(py[j].last), c);
    mean[c] = sum / scale_ / area;
  }
}

}  // namespace mb
