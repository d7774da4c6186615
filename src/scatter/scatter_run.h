#pragma once
// What `scatter` runs (docs/scattering.md §4): its options declared once as records, and every
// scattering technique on every light view and camera of a dataset against the exact
// in-scattering. The command adds the outputs; this is reachable from tests.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scatter/scatter_stats.h"
#include "scene/dataset.h"
#include "scene/scene.h"
#include "techniques/scatter/rectified_map.h"
#include "techniques/scatter/scatter_technique.h"
#include "util/option_record.h"

namespace mb {

struct ScatterRunOptions {
  std::vector<std::string> techniques;
  int reference_resolution = 0;
  double max_distance = 0;
  int light_resolution = 0;
  double guard_band = 0;
  std::string resample;
  double epipole_degrees = 0;
  std::string reference;
  double beta = 0;
  bool images = false;
  double error_scale = 0;
  TechniqueParams technique;  // the techniques' own options (their rows' records)
};

const std::vector<OptionRecord<ScatterRunOptions>>& scatter_run_options();
// The scatter stage's records and the scattering rows' own options.
std::vector<OptionSpec> scatter_run_option_specs();
// ScatterRunOptions of a config declaring scatter_run_option_specs(); InputError for an empty or
// unknown technique before any work.
ScatterRunOptions scatter_run_options_from(const Config& config);
// What a scattering sweep reads of them (sweep target scattering, docs/scattering.md §7): every
// measurement option but the techniques, the reference (pss_exact) and the images; and its
// ScatterRunOptions (no techniques, reference pss_exact, no images).
std::vector<OptionSpec> scatter_sweep_option_specs();
ScatterRunOptions scatter_sweep_options_from(const Config& config);
// The report's settings sentence: the light maps, the sky rays' length and every technique
// option's value.
std::string describe_scatter_settings(const ScatterRunOptions& run);
// What the scattering rows read of these options.
ScatterParams scatter_params(const ScatterRunOptions& options);

// A scene `scatter` can light: opaque, with cameras, and its medium (its own or the dataset's).
struct ScatterScene {
  Scene scene;
  MediumDesc medium;
};
// The dataset's scenes that have cameras; InputError, before any work, when none has, when one is
// translucent (the seed defines single scattering for opaque occluders), or when a scene with
// cameras has no medium or one that scatters nothing (albedo 0).
std::vector<ScatterScene> scatter_scenes(const DatasetDesc& dataset);

// sigma_s f E of a view ray along the unit `direction`, irradiance E = 1: the phase function's
// angle lies between the light's propagation direction (-to_light) and the direction from the
// scattering point towards the camera (-direction), so g > 0 brightens rays looking into the light.
double scattering_factor(const MediumDesc& medium, const Eigen::Vector3d& to_light,
                         const Eigen::Vector3d& direction);

// One light view and camera: per pixel the reference's in-scattering I_ref (scatter.reference),
// S_max and the surface's attenuated radiance, and per technique its I, statistics and wall-clock
// time. Bit-identical for any thread count (each pixel is answered on its own; sums run in pixel
// order).
struct ScatterFrameResult {
  std::string scene, view, camera;
  int width = 0, height = 0;
  std::vector<double> reference, s_max;
  std::vector<Eigen::Vector3d> surface;        // e^{-sigma_t s} L_s (linear RGB, irradiance E = 1)
  std::vector<std::vector<double>> inscatter;  // per technique, per pixel
  std::vector<ScatterStats> stats;
  std::vector<double> seconds;
  // Per technique, the rays its own answer failed on (an LP without a certified answer, a closed
  // form without a canonical distribution), answered lit and counted (docs/scattering.md §3.2).
  std::vector<size_t> failures;
  // Pixels whose view ray runs within scatter.epipole_degrees of the light's axis (towards or away
  // from the light), where a rectified row degenerates: answered and measured like the others,
  // and counted here so that the report says how many (docs/scattering.md §3.1).
  size_t epipole_pixels = 0;
  // The prefiltered rows' rectified map of this light view and camera (images only; else null).
  std::shared_ptr<const RectifiedMap> rectified;
};

// One row of `scatter`'s tables: a technique on one light view and camera, or on all of them.
struct ScatterRow {
  std::string technique, scene, view, camera;  // "all" in the overall rows
  ScatterStats stats;
  double seconds = 0;
  size_t failures = 0;  // rays answered lit because the technique's answer failed (of stats.pixels)
};

// The rows of `scatter`'s tables, gathered one light view and camera at a time (run_scatter hands
// each frame over as soon as it is computed and keeps none).
class ScatterRows {
 public:
  explicit ScatterRows(const std::vector<std::string>& techniques);
  void add(const ScatterFrameResult& result);
  // Each technique over every light view and camera ("all").
  const std::vector<ScatterRow>& overall() const { return overall_; }
  // Each technique on each light view and camera, technique-major as eval's per-view rows.
  std::vector<ScatterRow> per_frame() const;
  size_t frames() const { return epipole_lines_.size(); }
  // Per light view and camera, "<scene>/<view>/<camera>: N of M": the pixels near the epipole.
  const std::vector<std::string>& epipole_lines() const { return epipole_lines_; }

 private:
  std::vector<ScatterRow> overall_;
  std::vector<std::vector<ScatterRow>> frames_;  // per technique
  std::vector<std::string> epipole_lines_;
};

// Every light view (its layer 0 at scatter.reference_resolution, and at scatter.light_resolution
// for the prefiltered rows) and camera of every scene, each technique of `options`; `each` is
// called per light view and camera as soon as it is computed.
void run_scatter(const std::vector<ScatterScene>& scenes, const ScatterRunOptions& options,
                 int threads, bool quiet,
                 const std::function<void(const ScatterFrameResult&)>& each);

}  // namespace mb
