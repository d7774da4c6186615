// Closed-form solver throughput over a stream of fragments (issue 3 target: Hamburger 4MSM in
// double >= 100 M evaluations per second per core). Moments come from seeded random depth
// distributions of 1-8 atoms, biased as in eval; one thread.
#include <benchmark/benchmark.h>

#include <vector>

#include "moments/canonical.h"
#include "moments/chebyshev.h"
#include "moments/hamburger.h"
#include "moments/hausdorff.h"
#include "moments/tmsm.h"
#include "scene/procedural.h"

namespace mb {
namespace {

struct Stream {
  static constexpr int kFragments = 1 << 16;
  std::vector<double> b6, zf;  // 6 moments per fragment
  std::vector<float> b4f, zff;
  std::vector<double> trig;  // (sin 2πz, cos 2πz, sin 4πz, cos 4πz) moments of the same atoms
  std::vector<float> trigf;
  Stream() {
    SeededRandom rng(2026);
    const double star[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    for (int k = 0; k < kFragments; ++k) {
      int atoms = 1 + k % 8;
      double b[6] = {}, total = 0, z[8], w[8];
      for (int a = 0; a < atoms; ++a)
        total += w[a] = rng.uniform(0.05, 1), z[a] = rng.uniform(0, 1);
      for (int a = 0; a < atoms; ++a)
        for (int j = 0, p = 1; j < 6; ++j, ++p) b[j] += w[a] / total * std::pow(z[a], p);
      double t[4] = {};
      for (int a = 0; a < atoms; ++a) {
        const double phi = 2 * 3.141592653589793 * z[a];
        t[0] += w[a] / total * std::sin(phi), t[1] += w[a] / total * std::cos(phi);
        t[2] += w[a] / total * std::sin(2 * phi), t[3] += w[a] / total * std::cos(2 * phi);
      }
      bias_trigonometric_moments(t, 5e-5);
      for (int j = 0; j < 4; ++j) trig.push_back(t[j]), trigf.push_back(float(t[j]));
      bias_moments(b, 6, 3e-5, star);
      for (int j = 0; j < 6; ++j) b6.push_back(b[j]);
      for (int j = 0; j < 4; ++j) b4f.push_back(float(b[j]));
      zf.push_back(rng.uniform(0, 1));
      zff.push_back(float(zf.back()));
    }
  }
};
const Stream& stream() {
  static Stream s;
  return s;
}

template <class F>
void run(benchmark::State& state, F solve) {
  const Stream& s = stream();
  for (auto _ : state) {
    double sum = 0;
    for (int k = 0; k < Stream::kFragments; ++k) sum += solve(s, k);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * Stream::kFragments);
}

void BM_Hamburger4Double(benchmark::State& state) {
  run(state, [](const Stream& s, int k) { return hamburger4(&s.b6[6 * k], s.zf[k]).lower; });
}
// The batch form eval-style streams use: 4 moments per fragment, biased inside.
void BM_Hamburger4DoubleBatch(benchmark::State& state) {
  const Stream& s = stream();
  std::vector<double> b4, g(Stream::kFragments);
  for (int k = 0; k < Stream::kFragments; ++k)
    for (int j = 0; j < 4; ++j) b4.push_back(s.b6[6 * k + j]);
  for (auto _ : state) {
    hamburger4_lower_batch(b4.data(), s.zf.data(), g.data(), Stream::kFragments, 0.0);
    benchmark::DoNotOptimize(g.data());
  }
  state.SetItemsProcessed(state.iterations() * Stream::kFragments);
}
BENCHMARK(BM_Hamburger4DoubleBatch);

void BM_Hamburger4Float(benchmark::State& state) {
  run(state,
      [](const Stream& s, int k) { return double(hamburger4(&s.b4f[4 * k], s.zff[k]).lower); });
}
void BM_Hausdorff4(benchmark::State& state) {
  run(state, [](const Stream& s, int k) { return hausdorff4(&s.b6[6 * k], s.zf[k]).lower; });
}
void BM_Hamburger6(benchmark::State& state) {
  run(state, [](const Stream& s, int k) { return hamburger6(&s.b6[6 * k], s.zf[k]).lower; });
}
void BM_Vsm(benchmark::State& state) {
  run(state, [](const Stream& s, int k) { return vsm_bound(&s.b6[6 * k], s.zf[k], 0); });
}
void BM_TmsmDouble(benchmark::State& state) {
  run(state, [](const Stream& s, int k) { return tmsm(&s.trig[4 * k], s.zf[k], false).lower; });
}
void BM_TmsmFloat(benchmark::State& state) {
  run(state,
      [](const Stream& s, int k) { return double(tmsm(&s.trigf[4 * k], s.zff[k], false).lower); });
}
BENCHMARK(BM_Hamburger4Double);
BENCHMARK(BM_TmsmDouble);
BENCHMARK(BM_TmsmFloat);
BENCHMARK(BM_Hamburger4Float);
BENCHMARK(BM_Hausdorff4);
BENCHMARK(BM_Hamburger6);
BENCHMARK(BM_Vsm);

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
