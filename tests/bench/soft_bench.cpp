// Soft shadows' costs (issue 44, docs/soft-shadows.md): the area light's shadow against the hard
// reference per direction count N, and each soft technique per receiver, on the garden scene's
// `high` view at 512^2 under a 3-degree light, 2 threads, in one run.
#include <benchmark/benchmark.h>

#include <string>

#include "raster/render_view.h"
#include "scene/dataset.h"
#include "shadow/fragments.h"
#include "soft/area_light.h"
#include "soft/soft_techniques.h"

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

const Garden& garden() {
  static const Garden g = [] {
    Garden g{build_scene(
        parse_scene(std::string(MOMENTBENCH_SOURCE_DIR) + "/configs/scenes/garden.yaml"))};
    for (const auto& v : g.scene.views)
      if (v.name == "high") g.view = v;
    g.view.resolution = 512;
    g.stack = render_view(g.scene, g.view, kThreads);
    return g;
  }();
  return g;
}

// N = 0: the hard reference alone (the receivers and their filtered test); N > 0 adds the area
// light's N directions, each a rasterized stack and a filtered test per receiver.
void BM_Reference(benchmark::State& state) {
  const Garden& g = garden();
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
  state.SetLabel(n == 0 ? "hard reference" : "area light, N = " + std::to_string(n));
}
BENCHMARK(BM_Reference)->Arg(0)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

const char* const kTechniques[] = {"pcss_exact", "pcss",     "pcss_vsm",
                                   "pcss_esm",   "pcss_csm", "msm_soft"};

void BM_Technique(benchmark::State& state) {
  const Garden& g = garden();
  static Fragments f = collect_receivers(g.stack, g.kernel, g.bias, kThreads);
  static const SoftReceivers soft =
      light_receivers(g.scene, g.view, g.stack, f, g.kernel, g.bias, AreaLight{3, 16}, kThreads);
  static const ShadowMap map = layer0_shadow_map(g.stack);
  const std::string name = kTechniques[state.range(0)];
  for (auto _ : state) {
    SoftResult r = soft_shadow(name, map, f, soft, g.kernel, g.bias, SoftParams{}, kThreads);
    benchmark::DoNotOptimize(r.shadow.data());
  }
  state.counters["receivers_per_s"] =
      benchmark::Counter(double(f.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.SetLabel(name);
}
BENCHMARK(BM_Technique)->DenseRange(0, 5)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
