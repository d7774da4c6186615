// Rasterizer throughput: fragments per second for the city scene's views at 1024^2 (issue 2),
// 1 vs 2 threads in one run. Falls back to a procedural city when data/ has not been fetched.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "raster/render_view.h"
#include "scene/dataset.h"

namespace mb {
namespace {

const Scene& city() {
  static Scene scene = [] {
    std::string file = std::string(MOMENTBENCH_SOURCE_DIR) + "/configs/scenes/city.yaml";
    return build_scene(parse_scene(file));
  }();
  return scene;
}

void BM_RasterizeCityView(benchmark::State& state) {
  const Scene& scene = city();
  LightViewDesc view = scene.views[state.range(0)];
  view.resolution = 1024;
  int threads = int(state.range(1));
  size_t fragments = 0;
  for (auto _ : state) {
    LayerStack stack = render_view(scene, view, threads);
    fragments = stack.fragment_count();
    benchmark::DoNotOptimize(stack.depth.data());
  }
  state.counters["fragments"] = double(fragments);
  state.counters["triangles"] = double(scene.mesh.triangles.size());
  state.counters["fragments_per_s"] =
      benchmark::Counter(double(fragments) * state.iterations(), benchmark::Counter::kIsRate);
  state.SetLabel(view.name + ", " + std::to_string(threads) + " thread(s)");
}
BENCHMARK(BM_RasterizeCityView)
    ->ArgsProduct({{0, 1, 2, 3}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
