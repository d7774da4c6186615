#include "eval/evaluation.h"

#include <omp.h>

#include "lp/solution.h"
#include "raster/render_view.h"
#include "shadow/moment_map.h"
#include "util/error.h"
#include "util/parallel_errors.h"

namespace mb {

ViewData prepare_view(const Scene& scene, const LightViewDesc& view, const EvalSettings& settings) {
  LayerStack stack = render_view(scene, view, settings.threads);
  return ViewData{scene.name, view.name, layer0_shadow_map(stack),
                  collect_receivers(stack, settings.kernel, settings.bias, settings.threads)};
}

std::vector<ViewData> prepare_views(const DatasetDesc& dataset, int resolution,
                                    const EvalSettings& settings, bool quiet) {
  std::vector<Scene> scenes;
  for (const auto& file : dataset.scene_files) {
    scenes.push_back(build_scene(parse_scene(file)));
    for (size_t i = 0; i + 1 < scenes.size(); ++i)
      if (scenes[i].name == scenes.back().name)
        throw InputError(file + ": scene name '" + scenes.back().name +
                         "' is already used in dataset " + dataset.name +
                         " (outputs are named scene_view)");
  }
  if (resolution == 0) resolution = dataset.resolution;
  std::vector<ViewData> views;
  size_t total = 0;
  for (const auto& scene : scenes) total += scene.views.size();
  ProgressBar bar("render", total, quiet);
  for (const auto& scene : scenes)
    for (auto view : scene.views) {
      if (resolution > 0) view.resolution = resolution;
      views.push_back(prepare_view(scene, view, settings));
      bar.advance();
    }
  // A mean over no receivers would print 0 % for every technique (REFERENCE.md §3: receivers are
  // the light-facing fragments).
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  if (receivers == 0)
    throw InputError(
        dataset.file + ": dataset " + dataset.name +
        " has no receiver fragments (no surface faces the light in any view); nothing to evaluate");
  return views;
}

TechniqueResult evaluate_technique(const ViewData& view, const std::string& technique_name,
                                   const EvalSettings& settings, ProgressBar* progress) {
  const Fragments& f = view.fragments;
  TechniqueResult result;
  result.shadow.resize(f.size());
  auto probe = make_technique(technique_name, settings.technique);
  MomentMap moments;
  if (probe->basis().size() > 0)
    moments = compute_moment_map(view.map, probe->basis(), settings.kernel, probe->storage(),
                                 settings.threads);
  const size_t taps = size_t(settings.kernel.size) * settings.kernel.size;
  // Whole warm-start runs per thread (fragments are in texel order, so each run is contiguous).
  const std::vector<size_t> run_begin =
      lp::warm_run_begins(f.size(), f.width, [&](size_t k) { return f.texel[k]; });
  const size_t runs = run_begin.size() - 1;
  size_t failures = 0;
  ParallelErrors errors;  // each run's body captured: a throw must not leave the worksharing loop
#pragma omp parallel num_threads(settings.threads) reduction(+ : failures)
  {
    auto technique = make_technique(technique_name, settings.technique);
    const bool needs_distribution = technique->needs_distribution();
    std::vector<double> depths(taps), weights(taps);
#pragma omp for schedule(dynamic, 1)
    for (size_t run = 0; run < runs; ++run)
      errors.capture([&] {
        const size_t begin = run_begin[run], end = run_begin[run + 1];
        for (size_t k = begin; k < end; ++k) {
          const size_t texel = f.texel[k];
          FragmentInput in;
          if (moments.m > 0) in.moments = moments.at(texel);
          in.zf = f.ztest[k];
          in.pcf = f.pcf[k];
          in.oracle = f.oracle[k];
          in.fragment = k;
          in.layer = f.layer[k];
          in.column = int(texel % f.width);
          in.row = int(texel / f.width);
          in.run = lp::warm_run_of(texel, f.width);
          if (needs_distribution) {
            kernel_distribution(view.map, settings.kernel, in.column, in.row, depths, weights);
            in.kernel_depths = depths;
            in.kernel_weights = weights;
          }
          result.shadow[k] = technique->shadow(in);
        }
        if (progress) progress->advance(end - begin);
      });
    failures += technique->failures();
  }
  errors.rethrow();
  result.failures = failures;
  return result;
}

}  // namespace mb
