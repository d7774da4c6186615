#include "raster/rasterizer.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mb {

namespace {

// Coverage in fixed point: 8 sub-texel bits. With |coordinates| < 2^21 texels, edge-function
// products stay below 2^61, so every coverage decision is exact and shared edges agree.
constexpr int kSubpixelBits = 8;
constexpr int64_t kOne = int64_t(1) << kSubpixelBits;
constexpr int64_t kHalf = kOne / 2;
constexpr double kMaxCoordinate = double(1 << 21);
constexpr int kTile = 32;

struct TriangleSetup {
  int64_t x[3], y[3];
  bool tie[3];  // top-left rule per edge k -> k+1
  double x0, y0, z0, gx, gy, z_min, z_max;
  int col0, col1, row0, row1;  // inclusive texel range whose centres may be covered
  bool valid = false;
};

struct TileFragment {
  uint32_t texel;  // inside the tile: row * kTile + column
  uint32_t triangle;
  double depth;
};

int64_t floor_div(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// An edge of a counter-clockwise triangle covers the centres lying exactly on it only when it is
// a "top" or "left" edge. The two triangles sharing an edge traverse it in opposite directions,
// and exactly one of (dx, dy), (-dx, -dy) passes this test, so such a centre is covered once.
bool tie_included(int64_t dx, int64_t dy) {
  return dy > 0 || (dy == 0 && dx < 0);
}

TriangleSetup make_setup(const RasterInput& in, const std::array<uint32_t, 3>& tri) {
  TriangleSetup s;
  Eigen::Vector3d p[3] = {in.vertices[tri[0]], in.vertices[tri[1]], in.vertices[tri[2]]};
  for (const auto& v : p)
    if (!v.allFinite() || std::abs(v.x()) > kMaxCoordinate || std::abs(v.y()) > kMaxCoordinate)
      throw std::invalid_argument("rasterize: vertex outside the supported raster range");
  for (int k = 0; k < 3; ++k) {
    s.x[k] = std::llround(p[k].x() * kOne);
    s.y[k] = std::llround(p[k].y() * kOne);
  }
  int64_t area = (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
  if (area == 0) return s;  // degenerate after snapping: covers no centre
  if (area < 0) {
    std::swap(s.x[1], s.x[2]);
    std::swap(s.y[1], s.y[2]);
    std::swap(p[1], p[2]);
  }
  for (int k = 0; k < 3; ++k) {
    int n = (k + 1) % 3;
    s.tie[k] = tie_included(s.x[n] - s.x[k], s.y[n] - s.y[k]);
  }
  int64_t xmin = std::min({s.x[0], s.x[1], s.x[2]}), xmax = std::max({s.x[0], s.x[1], s.x[2]});
  int64_t ymin = std::min({s.y[0], s.y[1], s.y[2]}), ymax = std::max({s.y[0], s.y[1], s.y[2]});
  s.col0 = int(std::max<int64_t>(0, floor_div(xmin - kHalf + kOne - 1, kOne)));
  s.col1 = int(std::min<int64_t>(in.width - 1, floor_div(xmax - kHalf, kOne)));
  s.row0 = int(std::max<int64_t>(0, floor_div(ymin - kHalf + kOne - 1, kOne)));
  s.row1 = int(std::min<int64_t>(in.height - 1, floor_div(ymax - kHalf, kOne)));
  if (s.col0 > s.col1 || s.row0 > s.row1) return s;
  // The plane z = z0 + gx (x - x0) + gy (y - y0) of the unsnapped triangle.
  const std::optional<Eigen::Vector2d> gradient = plane_gradient(p[0], p[1], p[2]);
  s.x0 = p[0].x();
  s.y0 = p[0].y();
  s.z0 = p[0].z();
  s.gx = gradient ? gradient->x() : 0;
  s.gy = gradient ? gradient->y() : 0;
  // A nearly edge-on triangle has a steep plane; its depth is still bounded by its vertices'.
  s.z_min = std::min({p[0].z(), p[1].z(), p[2].z()});
  s.z_max = std::max({p[0].z(), p[1].z(), p[2].z()});
  s.valid = true;
  return s;
}

void rasterize_tile(const TriangleSetup& s, uint32_t triangle, int tile_col0, int tile_row0,
                    std::vector<TileFragment>& out) {
  int c0 = std::max(s.col0, tile_col0), c1 = std::min(s.col1, tile_col0 + kTile - 1);
  int r0 = std::max(s.row0, tile_row0), r1 = std::min(s.row1, tile_row0 + kTile - 1);
  if (c0 > c1 || r0 > r1) return;
  // Edge k: E_k(p) = (x[n]-x[k]) (py - y[k]) - (y[n]-y[k]) (px - x[k]); inside where all E_k > 0.
  int64_t ex[3], ey[3], row_start[3];
  int64_t px0 = c0 * kOne + kHalf, py0 = r0 * kOne + kHalf;
  for (int k = 0; k < 3; ++k) {
    int n = (k + 1) % 3;
    ex[k] = s.x[n] - s.x[k];
    ey[k] = s.y[n] - s.y[k];
    row_start[k] = ex[k] * (py0 - s.y[k]) - ey[k] * (px0 - s.x[k]);
  }
  for (int row = r0; row <= r1; ++row) {
    int64_t e[3] = {row_start[0], row_start[1], row_start[2]};
    double py = row + 0.5;
    for (int col = c0; col <= c1; ++col) {
      bool inside = true;
      for (int k = 0; k < 3; ++k) inside &= e[k] > 0 || (e[k] == 0 && s.tie[k]);
      if (inside) {
        double z = s.z0 + s.gx * (col + 0.5 - s.x0) + s.gy * (py - s.y0);
        z = std::clamp(z, s.z_min, s.z_max);
        out.push_back({uint32_t((row - tile_row0) * kTile + (col - tile_col0)), triangle, z});
      }
      for (int k = 0; k < 3; ++k) e[k] -= ey[k] * kOne;
    }
    for (int k = 0; k < 3; ++k) row_start[k] += ex[k] * kOne;
  }
}

// Orders a tile's fragments by (texel, depth, triangle): a stable counting sort by texel, then
// a stable insertion sort by depth inside each texel (a handful of layers). Fragments arrive in
// triangle order, so stability makes the triangle index the tie-breaker.
void sort_tile_fragments(std::vector<TileFragment>& fragments, std::vector<TileFragment>& scratch) {
  uint32_t start[kTile * kTile + 1] = {};
  for (const auto& f : fragments) ++start[f.texel + 1];
  for (int t = 0; t < kTile * kTile; ++t) start[t + 1] += start[t];
  scratch.resize(fragments.size());
  uint32_t cursor[kTile * kTile];
  std::copy(start, start + kTile * kTile, cursor);
  for (const auto& f : fragments) scratch[cursor[f.texel]++] = f;
  for (int t = 0; t < kTile * kTile; ++t) {
    for (uint32_t i = start[t] + 1; i < start[t + 1]; ++i) {
      TileFragment f = scratch[i];
      uint32_t j = i;
      for (; j > start[t] && scratch[j - 1].depth > f.depth; --j) scratch[j] = scratch[j - 1];
      scratch[j] = f;
    }
  }
  fragments.swap(scratch);
}

}  // namespace

std::optional<Eigen::Vector2d> plane_gradient(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                              const Eigen::Vector3d& c) {
  const double dx1 = b.x() - a.x(), dy1 = b.y() - a.y(), dz1 = b.z() - a.z();
  const double dx2 = c.x() - a.x(), dy2 = c.y() - a.y(), dz2 = c.z() - a.z();
  const double det = dx1 * dy2 - dx2 * dy1;
  if (det == 0) return std::nullopt;
  return Eigen::Vector2d((dz1 * dy2 - dz2 * dy1) / det, (dx1 * dz2 - dx2 * dz1) / det);
}

LayerStack rasterize(const RasterInput& in, int threads) {
  if (in.width <= 0 || in.height <= 0)
    throw std::invalid_argument("rasterize: resolution must be positive");
  if (in.facing.size() != in.triangles.size())
    throw std::invalid_argument("rasterize: one facing flag per triangle");
  const size_t triangle_count = in.triangles.size();
  std::vector<TriangleSetup> setups(triangle_count);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t t = 0; t < triangle_count; ++t) setups[t] = make_setup(in, in.triangles[t]);

  // Bin triangles to tiles in triangle order (serial, so each list is sorted by index).
  const int tiles_x = (in.width + kTile - 1) / kTile, tiles_y = (in.height + kTile - 1) / kTile;
  const size_t tile_count = size_t(tiles_x) * tiles_y;
  std::vector<uint32_t> bin_offsets(tile_count + 1, 0);
  auto for_each_tile = [&](const TriangleSetup& s, auto&& body) {
    for (int ty = s.row0 / kTile; ty <= s.row1 / kTile; ++ty)
      for (int tx = s.col0 / kTile; tx <= s.col1 / kTile; ++tx) body(size_t(ty) * tiles_x + tx);
  };
  for (const auto& s : setups)
    if (s.valid) for_each_tile(s, [&](size_t tile) { ++bin_offsets[tile + 1]; });
  for (size_t k = 0; k < tile_count; ++k) bin_offsets[k + 1] += bin_offsets[k];
  std::vector<uint32_t> bins(bin_offsets.back());
  {
    std::vector<uint32_t> cursor(bin_offsets.begin(), bin_offsets.end() - 1);
    for (size_t t = 0; t < triangle_count; ++t)
      if (setups[t].valid)
        for_each_tile(setups[t], [&](size_t tile) { bins[cursor[tile]++] = uint32_t(t); });
  }

  // Rasterize every tile independently, then order its fragments by (texel, depth, triangle).
  std::vector<std::vector<TileFragment>> tile_fragments(tile_count);
  LayerStack stack;
  stack.width = in.width;
  stack.height = in.height;
  stack.offsets.assign(stack.texel_count() + 1, 0);
#pragma omp parallel num_threads(threads)
  {
    std::vector<TileFragment> scratch;
#pragma omp for schedule(dynamic)
    for (size_t tile = 0; tile < tile_count; ++tile) {
      int col0 = int(tile % tiles_x) * kTile, row0 = int(tile / tiles_x) * kTile;
      auto& fragments = tile_fragments[tile];
      for (uint32_t k = bin_offsets[tile]; k < bin_offsets[tile + 1]; ++k)
        rasterize_tile(setups[bins[k]], bins[k], col0, row0, fragments);
      sort_tile_fragments(fragments, scratch);
      for (const auto& f : fragments) {
        size_t texel = size_t(row0 + f.texel / kTile) * in.width + (col0 + f.texel % kTile);
        ++stack.offsets[texel + 1];
      }
    }
  }
  for (size_t t = 0; t < stack.texel_count(); ++t) stack.offsets[t + 1] += stack.offsets[t];
  const size_t total = stack.offsets.back();
  stack.depth.resize(total);
  stack.facing.resize(total);
  stack.dz_dx.resize(total);
  stack.dz_dy.resize(total);
  if (in.keep_triangles) stack.triangle.resize(total);
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (size_t tile = 0; tile < tile_count; ++tile) {
    int col0 = int(tile % tiles_x) * kTile, row0 = int(tile / tiles_x) * kTile;
    size_t previous_texel = SIZE_MAX, slot = 0;
    for (const auto& f : tile_fragments[tile]) {
      size_t texel = size_t(row0 + f.texel / kTile) * in.width + (col0 + f.texel % kTile);
      slot = texel == previous_texel ? slot + 1 : stack.offsets[texel];
      previous_texel = texel;
      const TriangleSetup& s = setups[f.triangle];
      stack.depth[slot] = f.depth;
      stack.facing[slot] = in.facing[f.triangle];
      stack.dz_dx[slot] = s.gx;
      stack.dz_dy[slot] = s.gy;
      if (in.keep_triangles) stack.triangle[slot] = f.triangle;
    }
    std::vector<TileFragment>().swap(tile_fragments[tile]);
  }
  return stack;
}

}  // namespace mb
