#include "eval/evaluation.h"

#include <omp.h>

#include <algorithm>
#include <limits>

#include "eval/lp_view_solver.h"
#include "lp/solution.h"
#include "raster/render_view.h"
#include "shadow/moment_map.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"

namespace mb {

ViewData prepare_view(const Scene& scene, const LightViewDesc& view, const EvalSettings& settings) {
  LayerStack stack = render_view(scene, view, settings.threads);
  ViewData data{scene.name,
                view.name,
                layer0_shadow_map(stack, settings.blend),
                collect_receivers(stack, settings.kernel, settings.bias, settings.threads),
                {}};
  if (view.light_angle_deg > 0) {
    AreaLight light = settings.light;
    light.angle_deg = view.light_angle_deg;
    data.soft = light_receivers(scene, view, stack, data.fragments, settings.kernel, settings.bias,
                                light, settings.threads);
  }
  return data;
}

std::vector<LightViewDesc> rendered_views(const Scene& scene, const DatasetDesc& dataset,
                                          int resolution, const EvalSettings& settings) {
  std::vector<LightViewDesc> out;
  for (const auto& desc : scene.views) {
    LightViewDesc view = as_rendered(desc, dataset, resolution);
    if (view.light_angle_deg >= 0) {
      out.push_back(view);
      continue;
    }
    if (settings.light.angle_deg > 0 || dataset.light_angles.empty()) {
      view.light_angle_deg = settings.light.angle_deg;
      out.push_back(view);
      continue;
    }
    for (double angle : dataset.light_angles) {
      LightViewDesc v = view;
      v.light_angle_deg = angle;
      v.name = view.name + "_" + round_trip(angle) + "deg";
      out.push_back(v);
    }
  }
  return out;
}

LightViewDesc as_rendered(LightViewDesc view, const DatasetDesc& dataset, int resolution) {
  if (resolution == 0) resolution = dataset.resolution;
  if (resolution > 0) view.resolution = resolution;
  return view;
}

std::vector<Scene> build_dataset_scenes(const DatasetDesc& dataset) {
  std::vector<Scene> scenes;
  for (const auto& file : dataset.scene_files) {
    scenes.push_back(build_scene(parse_scene(file)));
    for (size_t i = 0; i + 1 < scenes.size(); ++i)
      if (scenes[i].name == scenes.back().name)
        throw InputError(file + ": scene name '" + scenes.back().name +
                         "' is already used in dataset " + dataset.name +
                         " (outputs are named scene_view)");
  }
  return scenes;
}

std::vector<ViewData> prepare_views(const DatasetDesc& dataset, int resolution,
                                    const EvalSettings& settings, bool quiet) {
  return prepare_views(build_dataset_scenes(dataset), dataset, resolution, settings, quiet);
}

std::vector<ViewData> prepare_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset,
                                    int resolution, const EvalSettings& settings, bool quiet) {
  std::vector<ViewData> views;
  size_t total = 0;
  for (const auto& scene : scenes)
    total += rendered_views(scene, dataset, resolution, settings).size();
  ProgressBar bar("render", total, quiet);
  for (const auto& scene : scenes)
    for (const auto& view : rendered_views(scene, dataset, resolution, settings)) {
      views.push_back(prepare_view(scene, view, settings));
      bar.advance();
    }
  // A mean over no receivers would print 0 % for every technique (docs/reference.md §3: receivers
  // are the light-facing fragments).
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  if (receivers == 0)
    throw InputError(
        dataset.file + ": dataset " + dataset.name +
        " has no receiver fragments (no surface faces the light in any view); nothing to evaluate");
  return views;
}

std::string describe_area_lights(const std::vector<ViewData>& views, const AreaLight& light) {
  std::vector<double> angles;
  for (const ViewData& v : views)
    if (v.soft.angle_deg > 0 &&
        std::find(angles.begin(), angles.end(), v.soft.angle_deg) == angles.end())
      angles.push_back(v.soft.angle_deg);
  if (angles.empty()) return "";
  std::string text =
      "; views lit by an area light: their reference is that light's shadow, not PCF "
      "(docs/soft-shadows.md §1), lights of ";
  for (size_t i = 0; i < angles.size(); ++i) text += (i ? ", " : "") + round_trip(angles[i]);
  return text + " degrees, " + std::to_string(light.directions) + " directions each; the " +
         role_name(TechniqueFamily::HardShadow, RowRole::Reference) + " row is the hard shadow";
}

void check_lp_interval(const std::vector<ViewData>& views, double lo, double hi) {
  for (const ViewData& v : views) {
    const std::vector<double>& depths = v.map.translucent() ? v.map.atom_depth : v.map.depth;
    // Outside the map is the far plane, 1 (docs/reference.md §3), which every kernel can reach.
    double min = 1, max = 1;
    for (double z : depths) min = std::min(min, z), max = std::max(max, z);
    if (lo <= min && max <= hi) continue;
    throw InputError("lp.lo, lp.hi: the LP's interval [" + round_trip(lo) + ", " + round_trip(hi) +
                     "] excludes depths of view " + v.scene + "/" + v.view + ", which lie in [" +
                     round_trip(min) + ", " + round_trip(max) +
                     "]; a kernel's depths must be admissible (docs/reference.md §2): expected "
                     "lp.lo <= " +
                     round_trip(min) + " and lp.hi >= " + round_trip(max));
  }
}

const TechniqueRow& shadow_row(const std::string& name) {
  return technique_row(name, {TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow});
}

bool is_view_reference(const std::string& technique, double light_angle_deg) {
  return technique_role(technique) == RowRole::Reference && !(light_angle_deg > 0);
}

double technique_darkening_bound(const std::string& name, const EvalSettings& settings) {
  if (shadow_row(name).family != TechniqueFamily::HardShadow)
    return std::numeric_limits<double>::infinity();
  return make_technique(name, settings.technique)->darkening_bound();
}

std::string technique_darkening_reason(const std::string& name, const EvalSettings& settings) {
  const TechniqueRow& row = shadow_row(name);
  if (row.family != TechniqueFamily::HardShadow) return row.unproven_reason;
  return make_technique(name, settings.technique)->darkening_reason();
}

std::map<std::string, std::string> darkening_reasons(const std::vector<std::string>& techniques,
                                                     const EvalSettings& settings,
                                                     const std::vector<ViewData>& views) {
  const bool area_light = !describe_area_lights(views, settings.light).empty();
  std::map<std::string, std::string> reasons;
  for (const auto& name : techniques)
    reasons[name] = area_light
                        ? "the reference is an area light's shadow, which no technique bounds"
                        : technique_darkening_reason(name, settings);
  return reasons;
}

TechniqueResult evaluate_technique(const ViewData& view, const std::string& technique_name,
                                   const EvalSettings& settings, ProgressBar* progress) {
  const Fragments& f = view.fragments;
  TechniqueResult result;
  if (shadow_row(technique_name).family == TechniqueFamily::SoftShadow) {
    SoftResult soft =
        soft_shadow(technique_name, view.map, f, view.soft, settings.kernel, settings.bias,
                    settings.soft, settings.threads, settings.technique);
    result.shadow = std::move(soft.shadow);
    result.failures = soft.failures;
    if (progress) progress->advance(f.size());
    return result;
  }
  auto probe = make_technique(technique_name, settings.technique);
  if (const lp::ProblemFactory* factory = probe->lp_factory()) {
    // The sweep's loop, so that eval's lp: and a sweep candidate are one computation.
    const std::vector<uint32_t> needs_lp = fragments_needing_lp(f, settings.technique.lp_beta);
    LpViewAnswers answers =
        solve_lp_view(view, needs_lp, probe->basis(), *factory, settings, progress);
    if (progress) progress->advance(f.size() - needs_lp.size());  // the skipped fragments
    result.shadow = std::move(answers.shadow);
    result.failures = answers.infeasible + answers.unstable;
    return result;
  }
  result.shadow.resize(f.size());
  MomentMap moments;
  if (probe->basis().size() > 0)
    moments = compute_moment_map(view.map, probe->basis(), settings.kernel, probe->storage(),
                                 settings.threads);
  const size_t taps = size_t(settings.kernel.size) * settings.kernel.size;
  // Closed forms answer each fragment on its own: any split of the work gives the same bits.
  constexpr size_t kBlock = 4096;
  const size_t blocks = (f.size() + kBlock - 1) / kBlock;
  size_t failures = 0, fallbacks = 0;
  ParallelErrors errors;  // each block captured: a throw must not leave the worksharing loop
#pragma omp parallel num_threads(settings.threads) reduction(+ : failures, fallbacks)
  {
    auto technique = make_technique(technique_name, settings.technique);
    const bool needs_distribution = technique->needs_distribution();
    std::vector<double> depths(taps), weights(taps), alphas(taps);
    std::vector<uint32_t> tap_offsets;
#pragma omp for schedule(dynamic, 1)
    for (size_t block = 0; block < blocks; ++block)
      errors.capture([&] {
        const size_t begin = block * kBlock, end = std::min(f.size(), begin + kBlock);
        for (size_t k = begin; k < end; ++k) {
          const size_t texel = f.texel[k];
          FragmentInput in;
          if (moments.m > 0) in.moments = moments.at(texel);
          in.zf = f.ztest[k];
          // Under an area light the `pcf` row is the hard shadow, so its error is the penumbra's.
          in.pcf = view.soft.hard.empty() ? f.pcf[k] : view.soft.hard[k];
          in.oracle = f.oracle[k];
          if (needs_distribution) {
            kernel_atoms(view.map, settings.kernel, int(texel % f.width), int(texel / f.width),
                         depths, weights, nullptr, &tap_offsets, &alphas);
            in.kernel_depths = depths;
            in.kernel_weights = weights;
            in.kernel_alpha = alphas;
            if (view.map.translucent()) in.tap_offsets = tap_offsets;
          }
          result.shadow[k] = technique->shadow(in);
        }
        if (progress) progress->advance(end - begin);
      });
    failures += technique->failures();
    fallbacks += technique->fallbacks();
  }
  errors.rethrow();
  result.failures = failures;
  result.fallbacks = fallbacks;
  return result;
}

}  // namespace mb
