#include "shadow/moment_map.h"

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
  if (map.translucent()) blend_translucent_texels(map, basis, r, stored);
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
