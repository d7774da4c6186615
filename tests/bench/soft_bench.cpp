// Soft shadows' costs (issue 44, docs/soft-shadows.md): the area light's shadow against the hard
// reference per direction count N, and each soft technique per receiver, on the garden scene's
// `high` view at 512^2 under a 3-degree light, 2 threads, in one run; and the blocker bounds by
// GLPK against our engine.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "lp/blocker_bounds.h"
#include "raster/render_view.h"
#include "scene/dataset.h"
#include "shadow/area_light.h"
#include "shadow/fragments.h"
#include "techniques/soft/soft_technique.h"

namespace mb {
namespace {

constexpr int kThreads = 2;

struct Garden {
  Scene scene;
  LightViewDesc view;
  LayerStack stack;
  GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  BiasParams bias;
};

Garden make_garden(int resolution) {
  Garden g{build_scene(
      parse_scene(std::string(MOMENTBENCH_SOURCE_DIR) + "/configs/scenes/garden.yaml"))};
  for (const auto& v : g.scene.views)
    if (v.name == "high") g.view = v;
  g.view.resolution = resolution;
  g.stack = render_view(g.scene, g.view, kThreads);
  return g;
}

// The `high` view at 512^2, or at `resolution`.
const Garden& garden(int resolution = 512) {
  static std::map<int, Garden> gardens;
  auto it = gardens.find(resolution);
  if (it == gardens.end()) it = gardens.emplace(resolution, make_garden(resolution)).first;
  return it->second;
}

// N = 0: the hard reference alone (the receivers and their filtered test); N > 0 adds the area
// light's N directions, each a rasterized stack and a filtered test per receiver.
void BM_Reference(benchmark::State& state) {
  const Garden& g = garden(int(state.range(1)));
  const int n = int(state.range(0));
  size_t receivers = 0;
  for (auto _ : state) {
    Fragments f = collect_receivers(g.stack, g.kernel, g.bias, kThreads);
    if (n > 0)
      light_receivers(g.scene, g.view, g.stack, f, g.kernel, g.bias, AreaLight{3, n}, kThreads);
    receivers = f.size();
    benchmark::DoNotOptimize(f.pcf.data());
  }
  state.counters["receivers"] = double(receivers);
  state.SetLabel((n == 0 ? "hard reference" : "area light, N = " + std::to_string(n)) + " at " +
                 std::to_string(state.range(1)) + "^2");
}
BENCHMARK(BM_Reference)
    ->ArgsProduct({{0, 16, 64}, {256, 512, 1024}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

const char* const kTechniques[] = {"pcss_exact", "pcss",     "pcss_vsm",          "pcss_esm",
                                   "pcss_csm",   "msm_soft", "msm_soft:lp:power4"};

void BM_Technique(benchmark::State& state) {
  const Garden& g = garden();
  static Fragments f = collect_receivers(g.stack, g.kernel, g.bias, kThreads);
  static const SoftReceivers soft =
      light_receivers(g.scene, g.view, g.stack, f, g.kernel, g.bias, AreaLight{3, 16}, kThreads);
  static const ShadowMap map = layer0_shadow_map(g.stack);
  const std::string name = kTechniques[state.range(0)];
  TechniqueParams lp_params;
  lp_params.lp.grid = 256;  // eval's lp.grid
  for (auto _ : state) {
    SoftResult r =
        soft_shadow(name, map, f, soft, g.kernel, g.bias, SoftParams{}, kThreads, lp_params);
    benchmark::DoNotOptimize(r.shadow.data());
  }
  state.counters["receivers_per_s"] =
      benchmark::Counter(double(f.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.SetLabel(name);
}
BENCHMARK(BM_Technique)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->UseRealTime();

// The blocker bounds of 27^2 search regions (docs/soft-shadows.md §3) with power4 on a 256 grid:
// Charnes and Cooper's LP by GLPK (0) against Dinkelbach's steps on our engine (1), on the same
// regions of receivers spread evenly over the view, those with a blocker in front of z_f.
void BM_BlockerBounds(benchmark::State& state) {
  const Garden& g = garden();
  static const Fragments f = collect_receivers(g.stack, g.kernel, g.bias, kThreads);
  static const ShadowMap map = layer0_shadow_map(g.stack);
  struct Region {
    std::vector<double> depths, points, moments;
    double zs = 0;
  };
  static const std::vector<Region> regions = [] {
    std::vector<Region> out;
    for (size_t k = 0; k < f.size() && out.size() < 200; k += 997) {
      const int x = int(f.texel[k] % f.width), y = int(f.texel[k] / f.width);
      Region r;
      r.zs = f.ztest[k];
      r.moments.assign(4, 0.0);
      bool blocker = false;
      for (int j = y - 13; j <= y + 13; ++j)
        for (int i = x - 13; i <= x + 13; ++i) {
          const double z = map.at(i, j);
          r.depths.push_back(z);
          blocker = blocker || z < r.zs;
          double zk = 1;
          for (double& m : r.moments) zk *= z, m += zk / 729;
        }
      if (!blocker) continue;
      for (int i = 0; i < 256; ++i) r.points.push_back(i / 255.0);
      r.points.insert(r.points.end(), r.depths.begin(), r.depths.end());
      r.points.push_back(r.zs);
      out.push_back(std::move(r));
    }
    return out;
  }();
  lp::Discretization grid;
  grid.grid = 256;
  const lp::ProblemFactory factory(Basis::parse({"power4"}), grid);
  const auto backend = lp::make_backend("fast");
  const std::vector<double> weights(729, 1.0 / 729);
  const bool ours = state.range(0) == 1;
  int lps = 0;
  for (auto _ : state) {
    lps = 0;
    for (const Region& r : regions) {
      const BlockerBounds b =
          ours ? blocker_bounds_dinkelbach(factory, r.depths, weights, r.zs, *backend)
               : blocker_bounds(factory, r.points, r.moments, r.zs);
      lps += b.lps;
      benchmark::DoNotOptimize(b.lo);
    }
  }
  state.counters["regions_per_s"] =
      benchmark::Counter(double(regions.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["lps_per_region"] = double(lps) / double(regions.size());
  state.SetLabel(ours ? "Dinkelbach, our engine" : "Charnes-Cooper, GLPK");
}
BENCHMARK(BM_BlockerBounds)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
