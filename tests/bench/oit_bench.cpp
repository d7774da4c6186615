// Order-independent transparency (issue 43): fragments per second of each reconstruction on one
// core over seeded random pixels of 1-30 fragments (the transparency dataset's range), and the LP
// per fragment with our engine against GLPK on the same pixels (the ratio of the two rows).
// The whole-frame number comes from scripts/bench_oit.sh.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "moments/canonical.h"
#include "moments/hamburger.h"
#include "scene/procedural.h"
#include "techniques/oit/oit_technique.h"

namespace mb {
namespace {

struct Pixels {
  std::vector<std::vector<double>> depth, alpha, warped;
  std::vector<std::vector<Rgb>> color;
  size_t fragments = 0;
  explicit Pixels(int count) {
    SeededRandom rng(43);
    for (int p = 0; p < count; ++p) {
      const int n = 1 + int(rng.uniform(0, 30));
      std::vector<double> z, a, u;
      for (int l = 0; l < n; ++l)
        z.push_back(rng.uniform(2, 12)), a.push_back(rng.uniform(0.05, 0.9));
      // The frame's warp maps [2, 12] onto [0, 1] (docs/transparency.md §2).
      const DepthWarp warp = DepthWarp::between(2, 12);
      for (double d : z) u.push_back(warp(d));
      depth.push_back(z), alpha.push_back(a), warped.push_back(u);
      color.push_back(std::vector<Rgb>(size_t(n), Rgb{0.5f, 0.5f, 0.5f}));
      fragments += size_t(n);
    }
  }
};

const Pixels& pixels(int count) {
  static Pixels many(4096), few(256);
  return count > 256 ? many : few;
}

void reconstruct(benchmark::State& state, const std::string& name, const OitParams& params,
                 int count) {
  const Pixels& px = pixels(count);
  auto technique = make_oit_technique(name, params);
  std::vector<double> t;
  for (auto _ : state) {
    for (size_t p = 0; p < px.depth.size(); ++p) {
      t.resize(px.depth[p].size());
      technique->transmittance({px.depth[p], px.alpha[p], px.color[p], kBackground}, px.warped[p],
                               t);
      benchmark::DoNotOptimize(t.data());
    }
  }
  state.counters["fragments/s"] =
      benchmark::Counter(double(px.fragments) * state.iterations(), benchmark::Counter::kIsRate);
}

void BM_Reconstruct(benchmark::State& state, const char* name) {
  reconstruct(state, name, {}, 4096);
}
BENCHMARK_CAPTURE(BM_Reconstruct, exact, "exact");
BENCHMARK_CAPTURE(BM_Reconstruct, wboit, "wboit");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_power4, "mboit_power4");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_power6, "mboit_power6");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_power8, "mboit_power8");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_trig2, "mboit_trig2");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_trig4, "mboit_trig4");
BENCHMARK_CAPTURE(BM_Reconstruct, mboit_power4_float, "mboit_power4_float");

// MBOIT's resolve pass alone for four power moments in double: per pixel its biased moments and
// total absorbance as the moment pass left them (computed once, outside the timing), per fragment
// the closed form (moments/hamburger.h, every fragment of the pixel at once) and T = e^{-A}.
void BM_ResolvePower4(benchmark::State& state) {
  const Pixels& px = pixels(4096);
  const double star[4] = {0, 0.375, 0, 0.375};
  std::vector<std::array<double, 4>> moments;
  std::vector<double> totals;
  std::vector<std::vector<double>> t;
  for (size_t p = 0; p < px.depth.size(); ++p) {
    const AbsorbanceDistribution d =
        absorbance_distribution({px.depth[p], px.alpha[p], px.color[p], kBackground}, px.warped[p]);
    std::array<double, 4> b = {};
    for (size_t i = 0; i < d.depths.size(); ++i) {
      double power = 1;
      for (int j = 0; j < 4; ++j) b[size_t(j)] += d.weights[i] * (power *= 2 * d.depths[i] - 1);
    }
    bias_moments(b.data(), 4, 1e-10, star);
    moments.push_back(b), totals.push_back(d.total);
    std::vector<double> tp;
    for (double u : px.warped[p]) tp.push_back(2 * u - 1);
    t.push_back(tp);
  }
  std::vector<double> g(64), out(64);
  for (auto _ : state) {
    for (size_t p = 0; p < moments.size(); ++p) {
      const size_t n = t[p].size();
      hamburger4_blend_batch(moments[p].data(), t[p].data(), n, 0.25, g.data());
      for (size_t l = 0; l < n; ++l) out[l] = std::exp(-totals[p] * g[l]);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.counters["fragments/s"] =
      benchmark::Counter(double(px.fragments) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ResolvePower4);

// The floor of any moment-based reconstruction in double with glibc's scalar libm: one log1p per
// fragment (its absorbance, -ln(1 - alpha)) and one exp (its transmittance, e^{-A}), nothing else.
void BM_TranscendentalFloor(benchmark::State& state) {
  const Pixels& px = pixels(4096);
  double sink = 0;
  for (auto _ : state) {
    for (size_t p = 0; p < px.alpha.size(); ++p)
      for (size_t l = 0; l < px.alpha[p].size(); ++l)
        sink += std::exp(-0.5 * -std::log1p(-px.alpha[p][l] * px.warped[p][l]));
    benchmark::DoNotOptimize(sink);
  }
  state.counters["fragments/s"] =
      benchmark::Counter(double(px.fragments) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TranscendentalFloor);

// lp:power4 per fragment, our engine (with its GLPK fallback) against GLPK alone, same pixels.
void BM_Lp(benchmark::State& state, const char* backend) {
  OitParams params;
  params.technique.lp_backend = backend;
  reconstruct(state, "lp:power4", params, 256);
}
BENCHMARK_CAPTURE(BM_Lp, fast, "fast")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Lp, glpk, "glpk")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
