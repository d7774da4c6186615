#include "scatter/scatter_run.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "eval/evaluation.h"
#include "raster/render_camera.h"
#include "raster/render_view.h"
#include "scatter/scatter_frames.h"
#include "techniques/lp_options.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"
#include "util/progress.h"

namespace mb {

namespace {

// The scattering rows others may be measured against (their rows' as_reference), by rank.
std::vector<std::string> reference_rows() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::Scattering))
    if (!row->as_reference.empty()) names.push_back(row->name);
  return names;
}

// "`exact`, the exact in-scattering ...; or `pss_exact`, ...".
std::string reference_rows_text() {
  std::string text;
  for (const std::string& name : reference_rows())
    text += (text.empty() ? "" : "; or ") + ("`" + name + "`, ") +
            technique_row(name, TechniqueFamily::Scattering).as_reference;
  return text;
}

}  // namespace

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
        "pss_lp:power4, pss_msm6, pss_csm and pss_msm4 of 0.0065, 0.0053, 0.0077 and 0.021, "
        "against 0.018, 0.027, 0.19 and 0.057 at 4 texels and 0.0096, 0.0060, 0.0050 and 0.010 "
        "at 256 (pss_lp and pss_msm6 are best near 64, pss_csm and pss_msm4 wider).",
        0, 8192},
       &ScatterRunOptions::guard_band},
      {{"scatter.resample",
        OptionType::String,
        "point",
        "How the rectified map reads the light map (docs/scattering.md §3.1): `point`, the "
        "nearest light texel's depth; `filtered`, seed 004 §2.3's Algorithm 1, a trilinear "
        "(mipmapped) sample of the light map's power moments over the rectified texel's "
        "footprint turned into two depths and weights, each warped into an inclination "
        "(pss_exact counts both with their weights; exact and raymarch never read the rectified "
        "map). `point` by default so that the pss rows' documented errors, all measured under "
        "it, stay true, although the seed and the measurements favour filtered: on the "
        "scattering house with the default 1024² maps it lowers pss_exact's mean error by 4 to "
        "11 % and the per-pixel flicker of pss_exact, pss_msm4 and pss_msm6 over 8 camera turns "
        "of 0.1 degree by 10 to 37 % (42 to 58 % at 256²), at 3 to 4 times the map's build time "
        "(docs/scattering.md §3.3).",
        -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(),
        {"point", "filtered"}},
       &ScatterRunOptions::resample},
      {{"scatter.epipole_degrees", OptionType::Number, "1",
        "View rays within this angle of the light's axis (towards the light or away from it), "
        "where a rectified row shrinks to a point (r = t sin theta), are counted apart and the "
        "count reported per light view and camera (docs/scattering.md §3.1); they are measured "
        "like the others. 1 degree: such a ray's end lies within 0.0175 of its length from the "
        "axis, under two texels of the rectified map for rays up to the scattering dataset's "
        "scale (about 15 units over 1024 texels of about 14 units).",
        0, 90},
       &ScatterRunOptions::epipole_degrees},
      {{"scatter.reference", OptionType::String,
        role_name(TechniqueFamily::Scattering, RowRole::Reference),
        "What errors.csv measures against (docs/scattering.md §4): " + reference_rows_text() + ".",
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        reference_rows()},
       &ScatterRunOptions::reference},
      {{"scatter.beta", OptionType::Number, "0.5",
        "The moment rows' blend G + beta (G+ - G) of the sharp lower and upper bounds on a "
        "ray's shadowed fraction (pss_msm4, pss_msm6, pss_lp; docs/scattering.md §3.2): 0 the "
        "lower bound (never too dark), 1 the upper (never too bright). 0.5: seed 004 §2.4's "
        "choice, the midpoint of the bounds, whose worst error over all distributions with the "
        "row's moments is least; on the scattering dataset also the least mean error of every "
        "moment row (results/FINDINGS.md §12; 0.25 on the house alone).",
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
  params.resample = options.resample == "filtered" ? Resample::Filtered : Resample::Point;
  params.beta = options.beta;
  return params;
}

std::vector<OptionSpec> scatter_run_option_specs() {
  std::vector<OptionSpec> specs = option_specs(scatter_run_options());
  for (auto& s : technique_option_specs({TechniqueFamily::Scattering})) specs.push_back(s);
  // The lp.* keys pss_lp reads (its row's family options); the others keep their defaults.
  const TechniqueRow& pss_lp = technique_row("pss_lp:", TechniqueFamily::Scattering);
  for (auto& s : lp_option_specs())
    if (std::find(pss_lp.family_options.begin(), pss_lp.family_options.end(), s.name) !=
        pss_lp.family_options.end())
      specs.push_back(s);
  return specs;
}

ScatterRunOptions scatter_run_options_from(const Config& config) {
  ScatterRunOptions run;
  read_options(config, scatter_run_options(), run);
  read_technique_options(config, run.technique);
  read_lp_params(config, run.technique);
  if (run.techniques.empty()) throw InputError("techniques: expected at least one technique");
  const ScatterParams params = scatter_params(run);  // the guard band's check
  for (const auto& name : run.techniques) make_scatter_technique(name, params);
  return run;
}

namespace {

// What a scattering sweep does not read of scatter's options: the rows it runs are its candidates
// and references, its reference is pss_exact, it writes no images.
bool sweep_reads(const std::string& key) {
  return key != "techniques" && key != "images" && key != "scatter.error_scale" &&
         key != "scatter.reference";
}

// The sweep declares the lp.* keys itself (sweep/sweep_run.cpp, sweep_target_specs).
bool is_lp_key(const std::string& key) {
  return key.rfind("lp.", 0) == 0;
}

}  // namespace

std::vector<OptionSpec> scatter_sweep_option_specs() {
  std::vector<OptionSpec> specs;
  for (auto& s : scatter_run_option_specs())
    if (sweep_reads(s.name) && !is_lp_key(s.name)) specs.push_back(s);
  return specs;
}

ScatterRunOptions scatter_sweep_options_from(const Config& config) {
  ScatterRunOptions run;
  read_declared_options(config, scatter_run_options(), run);
  read_technique_options(config, run.technique);
  read_lp_params(config, run.technique);  // the candidates' LP (pss_lp's lp.* keys)
  run.techniques.clear();
  run.reference = "pss_exact";
  run.images = false;
  scatter_params(run);  // the guard band's check
  return run;
}

std::string describe_scatter_settings(const ScatterRunOptions& run) {
  std::string own = technique_option_text({TechniqueFamily::Scattering}, run.technique);
  if (!own.empty()) own = ", " + own;
  return "light maps " + std::to_string(run.reference_resolution) + "², rays without a surface " +
         round_trip(run.max_distance) + " scene units" + own +
         ", irradiance E = 1 (docs/scattering.md §1); reference " + run.reference +
         "; rectified maps " + std::to_string(run.light_resolution) + "², guard band " +
         round_trip(run.guard_band) + " depth texels, " + run.resample + " resampling, beta " +
         round_trip(run.beta) + " (§3)";
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

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
      throw InputError(medium->where + ": key 'medium.albedo' of scene " + scene.name +
                       ": 0 scatters nothing (scatter measures errors relative to the "
                       "in-scattering; expected albedo in (0, 1], docs/scattering.md §1)");
    out.push_back({std::move(scene), *medium});
  }
  if (out.empty())
    throw InputError("dataset " + dataset.name +
                     ": no scene names a camera (scatter measures view rays of cameras; add "
                     "`cameras:` with position, target, fov and resolution to a scene file)");
  return out;
}

double scattering_factor(const MediumDesc& medium, const Eigen::Vector3d& to_light,
                         const Eigen::Vector3d& direction) {
  return medium.scattering() * medium.phase_value((-to_light).dot(-direction));
}

void run_scatter(const std::vector<ScatterScene>& scenes, const ScatterRunOptions& options,
                 int threads, bool quiet,
                 const std::function<void(const ScatterFrameResult&)>& each) {
  const ScatterParams params = scatter_params(options);
  const auto reference = make_scatter_technique(options.reference, params);
  std::vector<std::unique_ptr<ScatterTechnique>> techniques;
  for (const auto& name : options.techniques)
    techniques.push_back(make_scatter_technique(name, params));
  for (const ScatterScene& s : scenes) {
    std::vector<CameraImage> images;
    for (const auto& camera : s.scene.cameras)
      images.push_back(render_camera(s.scene, camera, threads));
    for (const LightViewDesc& view : s.scene.views) {
      const auto light = render_scatter_light(s.scene, view, options, threads);
      for (size_t c = 0; c < s.scene.cameras.size(); ++c) {
        const CameraDesc& camera = s.scene.cameras[c];
        const ScatterFrame frame = make_scatter_frame(s, light, camera, images[c], options);
        ProgressBar bar("scatter " + frame.name(), techniques.size() + 1, quiet);
        const ScatterSetup setup = frame.setup();
        ScatterFrameResult r;
        r.scene = s.scene.name, r.view = view.name, r.camera = camera.name;
        r.width = frame.width, r.height = frame.height;
        r.surface = frame.surface;
        r.s_max = frame.s_max;
        r.epipole_pixels = frame.epipole_pixels;
        if (options.images)
          r.rectified = std::make_shared<const RectifiedMap>(
              light->rectify(), camera, s.medium.extinction,
              RectifiedSettings{params.light_resolution, params.guard_band, params.resample});
        reference->prepare(setup);
        r.reference = frame_inscatter(*reference, frame, threads);
        bar.advance();
        for (auto& technique : techniques) {
          const auto start = std::chrono::steady_clock::now();
          technique->prepare(setup);
          const size_t failed_before = technique->failures();
          std::vector<double> inscatter = frame_inscatter(*technique, frame, threads);
          r.failures.push_back(technique->failures() - failed_before);
          ScatterStats stats;
          for (size_t p = 0; p < inscatter.size(); ++p)
            stats.add(inscatter[p], r.reference[p], r.s_max[p]);
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

ScatterRows::ScatterRows(const std::vector<std::string>& techniques) : frames_(techniques.size()) {
  for (const auto& name : techniques) overall_.push_back({name, "all", "all", "all", {}, 0});
}

void ScatterRows::add(const ScatterFrameResult& r) {
  for (size_t k = 0; k < overall_.size(); ++k) {
    frames_[k].push_back({overall_[k].technique, r.scene, r.view, r.camera, r.stats[k],
                          r.seconds[k], r.failures[k]});
    overall_[k].stats.merge(r.stats[k]);
    overall_[k].seconds += r.seconds[k];
    overall_[k].failures += r.failures[k];
  }
  epipole_lines_.push_back(r.scene + "/" + r.view + "/" + r.camera + ": " +
                           std::to_string(r.epipole_pixels) + " of " +
                           std::to_string(size_t(r.width) * r.height));
}

std::vector<ScatterRow> ScatterRows::per_frame() const {
  std::vector<ScatterRow> rows;
  for (const auto& frame : frames_) rows.insert(rows.end(), frame.begin(), frame.end());
  return rows;
}

}  // namespace mb
