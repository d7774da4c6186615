#include "shadow/moment_map.h"

#include <algorithm>

namespace mb {

namespace {

// A translucent map's texels (docs/reference.md §7): E_{Z_t}[b] = sum_i T(z_i) alpha_i b(z_i), what
// alpha blending b(z_i) front to back produces (in submission order: ShadowMap::blended_mass),
// written over the padded texels inside the map.
void blend_translucent_texels(const ShadowMap& map, const Basis& basis, int r,
                              std::vector<double>& stored) {
  const int m = int(basis.size()), w = map.width, pw = w + 2 * r;
  std::vector<double> values(map.atom_depth.size());
  const std::vector<double>& mass = map.blended_mass();  // what the blending gives each atom
  for (int j = 0; j < m; ++j) {
    basis[j].evaluate(map.atom_depth, values);
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t t = size_t(y) * w + x;
        double sum = 0;
        for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a)
          sum += mass[a] * values[a];
        stored[(size_t(y + r) * pw + x + r) * m + j] = sum;
      }
  }
}

// The same texels as a GPU blends them into a float or 16-bit target (seed 004 §4): the opaque pass
// or the clear writes the last atom's stored value, then each translucent surface blends over it
// in draw order, rounded to the format at every step (blend_stored). Sorted order draws back to
// front, which gives T(z_i) alpha_i in exact arithmetic. Written back as moments (load_moments),
// which store_moments turns into the same stored values again: they lie on the format's grid.
void blend_stored_texels(const ShadowMap& map, const Basis& basis, const MomentStorage& storage,
                         int r, std::vector<double>& stored) {
  const size_t m = basis.size(), w = size_t(map.width), pw = w + 2 * size_t(r);
  std::vector<double> values(map.atom_depth.size() * m), column(map.atom_depth.size());
  for (size_t j = 0; j < m; ++j) {
    basis[j].evaluate(map.atom_depth, column);
    for (size_t a = 0; a < column.size(); ++a) values[a * m + j] = column[a];
  }
  for (size_t a = 0; a < map.atom_depth.size(); ++a) {
    const std::vector<double> q = stored_values(storage, {values.data() + a * m, m});
    std::copy(q.begin(), q.end(), values.begin() + a * m);
  }
  const auto drawn = [&](uint64_t first, uint64_t last, uint64_t k) {
    return map.atom_draw.empty() ? last - k : map.atom_draw[first + k];
  };
  for (size_t t = 0; t < map.depth.size(); ++t) {
    const uint64_t first = map.atom_offsets[t], last = map.atom_offsets[t + 1] - 1;
    double* texel = stored.data() + ((t / w + r) * pw + t % w + r) * m;
    std::copy_n(values.data() + last * m, m, texel);
    round_stored(storage, {texel, m});
    for (uint64_t k = 1; k <= last - first; ++k) {
      const uint64_t a = drawn(first, last, k);
      blend_stored(storage, {texel, m}, {values.data() + a * m, m}, map.atom_alpha[a]);
    }
    load_moments(storage, {texel, m});
  }
}

}  // namespace

MomentMap compute_moment_map(const ShadowMap& map, const Basis& basis, const GaussianKernel& kernel,
                             const MomentStorage& storage, int threads) {
  const int m = int(basis.size()), r = kernel.radius();
  const int w = map.width, h = map.height, pw = w + 2 * r, ph = h + 2 * r;
  // Padded stored values: outside the map is the far plane, depth 1 (docs/reference.md §3).
  std::vector<double> padded_depth(size_t(pw) * ph, 1.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      padded_depth[size_t(y + r) * pw + x + r] = map.depth[size_t(y) * w + x];
  std::vector<double> stored(size_t(pw) * ph * m), column(padded_depth.size());
  for (int j = 0; j < m; ++j) {
    basis[j].evaluate(padded_depth, column);
    for (size_t t = 0; t < column.size(); ++t) stored[t * m + j] = column[t];
  }
  if (map.translucent() && storage.kind == StorageKind::Double)
    blend_translucent_texels(map, basis, r, stored);
  else if (map.translucent())
    blend_stored_texels(map, basis, storage, r, stored);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t t = 0; t < padded_depth.size(); ++t)
    store_moments(storage, {stored.data() + t * m, size_t(m)});

  // Horizontal pass over the padded rows, then vertical; each sum in a fixed tap order.
  std::vector<double> horizontal(size_t(w) * ph * m);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int y = 0; y < ph; ++y)
    for (int x = 0; x < w; ++x)
      for (int j = 0; j < m; ++j) {
        double sum = 0;
        for (int d = 0; d < kernel.size; ++d)
          sum += kernel.weights[d] * stored[(size_t(y) * pw + x + d) * m + j];
        horizontal[(size_t(y) * w + x) * m + j] = sum;
      }
  MomentMap out{w, h, m, std::vector<double>(size_t(w) * h * m)};
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double* b = out.values.data() + (size_t(y) * w + x) * m;
      for (int j = 0; j < m; ++j) {
        double sum = 0;
        for (int d = 0; d < kernel.size; ++d)
          sum += kernel.weights[d] * horizontal[(size_t(y + d) * w + x) * m + j];
        b[j] = sum;
      }
      load_moments(storage, {b, size_t(m)});
    }
  return out;
}

}  // namespace mb
