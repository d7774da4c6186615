#include "scatter/scatter_run.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "eval/evaluation.h"
#include "raster/render_camera.h"
#include "raster/render_view.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"
#include "util/progress.h"

namespace mb {

// `techniques` chooses the rows; images and their scale change no measured number.
const std::vector<OptionRecord<ScatterRunOptions>>& scatter_run_options() {
  static const std::vector<OptionRecord<ScatterRunOptions>> records{
      {selects_runs({"techniques", OptionType::StringList,
                     default_techniques(TechniqueFamily::Scattering),
                     "Single-scattering techniques (docs/scattering.md §3): the scattering rows of "
                     "`momentbench options techniques` (exact, the reference itself as a sanity "
                     "row; raymarch:<N>)."}),
       &ScatterRunOptions::techniques},
      {{"scatter.reference_resolution", OptionType::Integer, "1024",
        "Resolution of the light view's hard shadow map (layer 0 of its stack) that the exact "
        "reference and ray marching test against (docs/scattering.md §2). 1024: about 70 texels "
        "per scene unit on the scattering dataset's 14-unit ground, so the house's 0.2-unit walls "
        "and its window frames span 14 texels or more, while the reference's walk (its cost "
        "linear in the texels a ray crosses) stays at a few seconds per 360 x 240 camera.",
        1, 16384},
       &ScatterRunOptions::reference_resolution},
      {{"scatter.max_distance", OptionType::Number, "100",
        "Length of the view ray of a pixel that sees no surface, in scene units "
        "(docs/scattering.md §1). 100: far beyond the scattering dataset's scenes (about 15 "
        "units across), where its medium's transmittance (sigma_t = 0.12) is e^-12, so a sky "
        "pixel's in-scattering is that of an infinite ray to about 1e-5 of S_max.",
        1e-9, 1e9},
       &ScatterRunOptions::max_distance},
      {{"scatter.light_resolution", OptionType::Integer, "1024",
        "The prefiltered rows' maps (docs/scattering.md §3.1): the light view's layer 0 that the "
        "rectified map resamples is rendered at this resolution, and the rectified map has as "
        "many texels along the light rays' distance r and as many rows along their azimuth phi. "
        "1024: seed 004 §2.6's shadow maps, 1024².",
        1, 16384},
       &ScatterRunOptions::light_resolution},
      {{"scatter.guard_band", OptionType::Number, "64",
        "Depth texels (of scatter.light_resolution across a row's normalised depth [0, 1]) left "
        "free at either end of each rectified row's range of inclinations, beyond those of the "
        "camera's view rays (seed 004 §2.2's guard band; docs/scattering.md §3.1). Surfaces "
        "outside the range are clamped to its ends, and empty light rays lie at depth 1: too "
        "close to a ray's depth, a moment or Fourier reconstruction smears them across it. 64 "
        "(the rays fill the middle 7/8): on scattering_tiny, mean errors against exact of "
        "pss_lp:power4, pss_msm6, pss_csm and pss_msm4 of 0.0067, 0.0055, 0.0077 and 0.075, "
        "against 0.018, 0.027, 0.19 and 0.12 at 4 texels and 0.0099, 0.0060, 0.0050 and 0.047 "
        "at 256 (pss_lp is best near 64).",
        0, 8192},
       &ScatterRunOptions::guard_band},
      {{"scatter.epipole_degrees", OptionType::Number, "1",
        "View rays within this angle of the light's axis (towards the light or away from it), "
        "where a rectified row shrinks to a point (r = t sin theta), are counted apart and the "
        "count reported per light view and camera (docs/scattering.md §3.1); they are measured "
        "like the others. 1 degree: such a ray's end lies within 0.0175 of its length from the "
        "axis, under two texels of the rectified map for rays up to the scattering dataset's "
        "scale (about 15 units over 1024 texels of about 14 units).",
        0, 90},
       &ScatterRunOptions::epipole_degrees},
      {{"scatter.reference",
        OptionType::String,
        "exact",
        "What errors.csv measures against (docs/scattering.md §4): `exact`, the walk over the "
        "hard shadow map (§2), or `pss_exact`, the rectified row's own visibility (§3.2), so "
        "that a moment row's error is its moments' loss alone.",
        -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(),
        {"exact", "pss_exact"}},
       &ScatterRunOptions::reference},
      {{"scatter.beta", OptionType::Number, "0.5",
        "The moment rows' blend G + beta (G+ - G) of the sharp lower and upper bounds on a "
        "ray's shadowed fraction (pss_msm4, pss_msm6, pss_lp; docs/scattering.md §3.2): 0 the "
        "lower bound (never too dark), 1 the upper (never too bright). 0.5: seed 004 §2.4's "
        "choice, the least worst-case error.",
        0, 1},
       &ScatterRunOptions::beta},
      {measures_nothing({"images", OptionType::Boolean, "true",
                         "Per light view, camera and technique: the final colour, the "
                         "in-scattering alone, its error in false colour, and a contact sheet "
                         "(images/)."}),
       &ScatterRunOptions::images},
      {measures_nothing(
           {"scatter.error_scale", OptionType::Number, "0.25",
            "The error images' colour bar ends at this error (a pixel's absolute difference from "
            "the reference, divided by its S_max; docs/scattering.md §4): 0.25, where "
            "a ray's error is a quarter of what it could scatter.",
            1e-6, 1}),
       &ScatterRunOptions::error_scale},
  };
  return records;
}

ScatterParams scatter_params(const ScatterRunOptions& options) {
  if (!(2 * options.guard_band < options.light_resolution))
    throw InputError("scatter.guard_band: " + round_trip(options.guard_band) +
                     " depth texels at either end leave no depth range of a rectified row of " +
                     std::to_string(options.light_resolution) +
                     " (scatter.light_resolution); expected below half of it");
  ScatterParams params;
  params.technique = options.technique;
  params.light_resolution = options.light_resolution;
  params.guard_band = options.guard_band;
  params.beta = options.beta;
  return params;
}

std::vector<OptionSpec> scatter_run_option_specs() {
  std::vector<OptionSpec> specs = option_specs(scatter_run_options());
  for (auto& s : technique_option_specs({TechniqueFamily::Scattering})) specs.push_back(s);
  return specs;
}

ScatterRunOptions scatter_run_options_from(const Config& config) {
  ScatterRunOptions run;
  read_options(config, scatter_run_options(), run);
  read_technique_options(config, run.technique);
  if (run.techniques.empty()) throw InputError("techniques: expected at least one technique");
  const ScatterParams params = scatter_params(run);  // the guard band's check
  for (const auto& name : run.techniques) make_scatter_technique(name, params);
  return run;
}

std::string describe_scatter_settings(const ScatterRunOptions& run) {
  std::string own = technique_option_text({TechniqueFamily::Scattering}, run.technique);
  if (!own.empty()) own = ", " + own;
  return "light maps " + std::to_string(run.reference_resolution) + "², rays without a surface " +
         round_trip(run.max_distance) + " scene units" + own +
         ", irradiance E = 1 (docs/scattering.md §1); reference " + run.reference +
         "; rectified maps " + std::to_string(run.light_resolution) + "², guard band " +
         round_trip(run.guard_band) + " depth texels, beta " + round_trip(run.beta) + " (§3)";
}

std::vector<ScatterScene> scatter_scenes(const DatasetDesc& dataset) {
  std::vector<ScatterScene> out;
  for (Scene& scene : build_dataset_scenes(dataset)) {
    if (scene.translucent())
      throw InputError("scene " + scene.name + " of dataset " + dataset.name +
                       ": has translucent parts (opacity < 1); scatter measures single scattering "
                       "past opaque occluders only (seed 004 §2; expected every part opaque)");
    if (scene.cameras.empty()) continue;
    const std::optional<MediumDesc> medium = scene.medium ? scene.medium : dataset.medium;
    if (!medium)
      throw InputError("scene " + scene.name + " of dataset " + dataset.name +
                       ": no medium (expected `medium: {extinction, albedo, phase, g}` in the "
                       "scene file or the dataset file)");
    if (!(medium->albedo > 0))
      throw InputError(medium->where + ": medium of scene " + scene.name +
                       ": albedo 0 scatters nothing (scatter measures errors relative to the "
                       "in-scattering; expected albedo in (0, 1])");
    out.push_back({std::move(scene), *medium});
  }
  if (out.empty())
    throw InputError("dataset " + dataset.name +
                     ": no scene names a camera (scatter measures view rays of cameras; add "
                     "`cameras:` with position, target, fov and resolution to a scene file)");
  return out;
}

namespace {

// A camera's view rays, the surfaces they end at and those surfaces' attenuated radiance.
struct CameraRays {
  std::vector<ScatterRay> rays;
  std::vector<Eigen::Vector3d> surface;
};

// L_s of the nearest surface: its diffuse colour times max(0, n . l) / pi, shadowed by the same
// map (offset 1.5 texels along its normal against acne), then attenuated by exp(-sigma_t s).
// Only the images show it; no error reads it.
CameraRays camera_rays(const ScatterScene& s, const CameraDesc& camera, const CameraImage& image,
                       const LightDepthMap& light, double max_distance) {
  const CameraFrame frame(camera);
  const Eigen::Vector3d to_light = light.frame->to_light();
  const double offset = 1.5 * light.frame->world_per_texel();
  CameraRays out;
  out.rays.resize(size_t(image.width) * image.height);
  out.surface.assign(out.rays.size(), Eigen::Vector3d::Zero());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t p = size_t(y) * image.width + x;
      ScatterRay& ray = out.rays[p];
      ray.direction = frame.ray(x, y), ray.pixel = p, ray.length = max_distance;
      if (image.offsets[p] == image.offsets[p + 1]) continue;
      const size_t f = image.offsets[p];
      ray.length = (image.point[f] - frame.position()).norm();
      const auto& tri = s.scene.mesh.triangles[image.triangle[f]];
      const auto& v = s.scene.mesh.vertices;
      Eigen::Vector3d n = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).normalized();
      if (s.scene.two_sided[image.triangle[f]] && n.dot(to_light) < 0) n = -n;
      const double cosine = n.dot(to_light);
      if (!(cosine > 0) || !light.lit(image.point[f] + offset * n)) continue;
      out.surface[p] = s.scene.color[s.scene.part[image.triangle[f]]] *
                       (cosine / std::numbers::pi) * std::exp(-s.medium.extinction * ray.length);
    }
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// L of every ray by one technique, in parallel over image rows.
std::vector<double> lit_lengths(const ScatterTechnique& technique,
                                const std::vector<ScatterRay>& rays, int width, int threads) {
  std::vector<double> out(rays.size());
  const int rows = int(rays.size() / size_t(width));
  ParallelErrors parallel;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int y = 0; y < rows; ++y)
    parallel.capture([&] {
      for (size_t p = size_t(y) * width; p < size_t(y + 1) * width; ++p)
        out[p] = technique.lit_length(rays[p]);
    });
  parallel.rethrow();
  return out;
}

}  // namespace

double scattering_factor(const MediumDesc& medium, const Eigen::Vector3d& to_light,
                         const Eigen::Vector3d& direction) {
  return medium.scattering() * medium.phase_value((-to_light).dot(-direction));
}

void run_scatter(const std::vector<ScatterScene>& scenes, const ScatterRunOptions& options,
                 int threads, bool quiet,
                 const std::function<void(const ScatterFrameResult&)>& each) {
  const ScatterParams params = scatter_params(options);
  const auto reference = make_scatter_technique(options.reference, params);
  const double epipole_cos = std::cos(options.epipole_degrees * std::numbers::pi / 180);
  std::vector<std::unique_ptr<ScatterTechnique>> techniques;
  for (const auto& name : options.techniques)
    techniques.push_back(make_scatter_technique(name, params));
  for (const ScatterScene& s : scenes) {
    std::vector<CameraImage> images;
    for (const auto& camera : s.scene.cameras)
      images.push_back(render_camera(s.scene, camera, threads));
    for (LightViewDesc view : s.scene.views) {
      view.resolution = options.reference_resolution;
      check_render_memory(view.resolution, "scatter.reference_resolution");
      const LayerStack stack = render_view(s.scene, view, threads);
      const LightFrame light_frame(view, s.scene.mesh.vertices);  // render_view's projection
      const LightDepthMap light(light_frame, stack);
      // The prefiltered rows' map: the same view at scatter.light_resolution (render_view fits
      // the same projection to the scene at any resolution).
      std::unique_ptr<LayerStack> rectify_stack;
      std::unique_ptr<LightFrame> rectify_frame;
      std::unique_ptr<LightDepthMap> rectify_light;
      const LightDepthMap* rectify = &light;
      if (options.light_resolution != options.reference_resolution) {
        LightViewDesc low = view;
        low.resolution = options.light_resolution;
        check_render_memory(low.resolution, "scatter.light_resolution");
        rectify_stack = std::make_unique<LayerStack>(render_view(s.scene, low, threads));
        rectify_frame = std::make_unique<LightFrame>(low, s.scene.mesh.vertices);
        rectify_light = std::make_unique<LightDepthMap>(*rectify_frame, *rectify_stack);
        rectify = rectify_light.get();
      }
      const MediumDesc& medium = s.medium;
      for (size_t c = 0; c < s.scene.cameras.size(); ++c) {
        const CameraDesc& camera = s.scene.cameras[c];
        ProgressBar bar("scatter " + s.scene.name + "/" + view.name + "/" + camera.name,
                        techniques.size() + 1, quiet);
        const CameraRays rays = camera_rays(s, camera, images[c], light, options.max_distance);
        const ScatterSetup setup{&light,          &s.scene,          &view,  &camera,
                                 camera.position, medium.extinction, rectify};
        ScatterFrameResult r;
        r.scene = s.scene.name, r.view = view.name, r.camera = camera.name;
        r.width = images[c].width, r.height = images[c].height;
        r.surface = rays.surface;
        if (options.images)
          r.rectified = std::make_shared<const RectifiedMap>(
              *rectify, camera, medium.extinction,
              RectifiedSettings{params.light_resolution, params.guard_band});
        std::vector<double> factor(rays.rays.size());
        for (size_t p = 0; p < factor.size(); ++p) {
          const ScatterRay& ray = rays.rays[p];
          if (std::abs(ray.direction.dot(light.frame->to_light())) > epipole_cos)
            ++r.epipole_pixels;
          factor[p] = scattering_factor(medium, light.frame->to_light(), ray.direction);
          r.s_max.push_back(factor[p] * transmittance_integral(0, ray.length, medium.extinction));
        }
        reference->prepare(setup);
        r.reference = lit_lengths(*reference, rays.rays, r.width, threads);
        for (size_t p = 0; p < factor.size(); ++p) r.reference[p] *= factor[p];
        bar.advance();
        for (auto& technique : techniques) {
          const auto start = std::chrono::steady_clock::now();
          technique->prepare(setup);
          std::vector<double> inscatter = lit_lengths(*technique, rays.rays, r.width, threads);
          ScatterStats stats;
          for (size_t p = 0; p < factor.size(); ++p) {
            inscatter[p] *= factor[p];
            stats.add(inscatter[p], r.reference[p], r.s_max[p]);
          }
          r.seconds.push_back(seconds_since(start));
          r.inscatter.push_back(std::move(inscatter));
          r.stats.push_back(stats);
          bar.advance();
        }
        bar.finish();
        each(r);
      }
    }
  }
}

}  // namespace mb
