#include "oit/oit_run.h"

#include <omp.h>

#include <chrono>

#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"
#include "util/progress.h"

namespace mb {

// `techniques` chooses the rows, not their numbers; the images and their colour scales change no
// measured number (OptionEffect, docs/sweeps.md "Identity").
const std::vector<OptionRecord<OitRunOptions>>& oit_run_options() {
  static const std::vector<OptionRecord<OitRunOptions>> records{
      {selects_runs({"techniques", OptionType::StringList,
                     default_techniques(TechniqueFamily::Transmittance),
                     "Transparency techniques (docs/transparency.md §3): the transmittance rows of "
                     "`momentbench "
                     "options techniques` (the sorted composite, unsorted, wboit, the MBOIT closed "
                     "forms, or "
                     "lp:<basis> on the warped depth, e.g. lp:power4, lp:trig4)."}),
       &OitRunOptions::techniques},
      {measures_nothing(
           {"images", OptionType::Boolean, "true",
            "Per camera: the reference and each technique's composite, its CIEDE2000 difference in "
            "false colour, and a contact sheet (images/)."}),
       &OitRunOptions::images},
      {measures_nothing(
           {"deep_frames", OptionType::Boolean, "true",
            "Write each camera's deep frame (every fragment's depth, alpha and colour) as deep "
            "OpenEXR (frames/)."}),
       &OitRunOptions::deep_frames},
      {measures_nothing({"delta_e_scale", OptionType::Number, "10",
                         "CIEDE2000 at the top of the difference images' colour bar.", 1e-6, 1e3}),
       &OitRunOptions::delta_e_scale},
  };
  return records;
}

void check_frame_has_transparency(const DeepFrame& frame, const std::string& scene) {
  if (frame.fragments() > 0) return;
  throw InputError("camera " + scene + "/" + frame.camera +
                   ": sees no transparent geometry in front of the opaque surfaces (expected a "
                   "part with opacity < 1 in its view; oit measures nothing there)");
}

std::vector<SceneFrame> render_dataset_frames(const DatasetDesc& dataset, int threads) {
  const std::vector<Scene> scenes = build_dataset_scenes(dataset);
  std::vector<SceneFrame> frames;
  for (const auto& scene : scenes)
    for (const auto& camera : scene.cameras) {
      frames.push_back({scene.name, render_deep_frame(scene, camera, threads)});
      check_frame_has_transparency(frames.back().frame, scene.name);
    }
  if (frames.empty())
    throw InputError(
        "dataset " + dataset.name +
        ": no scene names a camera (transparency is measured on cameras; add `cameras:` with "
        "position, target, fov and resolution to a scene file)");
  return frames;
}

namespace {

// What every technique is compared with, computed once per frame: per fragment (frame order) the
// warped depth and the exact transmittance, per pixel the exact composite and its CIELAB value.
struct FrameReference {
  std::vector<double> warped, transmittance;
  std::vector<Rgb> composite;
  std::vector<Lab> lab;
};

FrameReference frame_reference(const DeepFrame& frame, const LabConverter& lab, WarpKind kind,
                               DepthRangeKind range) {
  const DepthWarp warp = frame_warp(frame, kind, range);
  FrameReference r;
  r.warped.resize(frame.fragments()), r.transmittance.resize(frame.fragments());
  r.composite.resize(frame.pixels()), r.lab.resize(frame.pixels());
  for (size_t f = 0; f < frame.fragments(); ++f) r.warped[f] = warp(frame.depth[f]);
  for (size_t p = 0; p < frame.pixels(); ++p) {
    const PixelFragments px = pixel_of(frame, p);
    const std::span<double> t(r.transmittance.data() + frame.offsets[p], px.size());
    exact_transmittance(px, t);
    r.composite[p] = composite(px, t, total_transmittance(px));
    r.lab[p] = lab.lab(r.composite[p]);
  }
  return r;
}

// One technique over the frame; composite, per-pixel errors, in pixel order.
void run_technique(const DeepFrame& frame, const FrameReference& reference, const std::string& name,
                   const OitParams& params, int threads, const LabConverter& lab,
                   std::vector<Rgb>& composite_out, std::vector<PixelError>& errors,
                   size_t& failures) {
  const size_t pixels = frame.pixels();
  const int rows = frame.height;
  ParallelErrors parallel;
  size_t failed = 0;
#pragma omp parallel num_threads(threads) reduction(+ : failed)
  {
    auto technique = make_oit_technique(name, params);
    std::vector<double> t;
#pragma omp for schedule(dynamic, 1)
    for (int y = 0; y < rows; ++y)
      parallel.capture([&] {
        for (size_t p = size_t(y) * frame.width; p < size_t(y + 1) * frame.width && p < pixels;
             ++p) {
          const PixelFragments px = pixel_of(frame, p);
          const size_t first = frame.offsets[p], n = px.size();
          const std::span<const double> warped(reference.warped.data() + first, n),
              t_ref(reference.transmittance.data() + first, n);
          t.resize(n);
          technique->transmittance(px, warped, t);
          effective_transmittance(*technique, px, t);
          composite_out[p] = composite(px, t, total_transmittance(px));
          errors[p] = pixel_error(px, t_ref, t, reference.composite[p], reference.lab[p],
                                  composite_out[p], lab);
        }
      });
    failed += technique->failures();
  }
  parallel.rethrow();
  failures = failed;
}

}  // namespace

OitRows::OitRows(const std::vector<std::string>& techniques) : cameras_(techniques.size()) {
  for (const auto& name : techniques) overall_.push_back({name, "all", {}, 0});
}

void OitRows::add(const OitFrameResult& result) {
  for (size_t k = 0; k < overall_.size(); ++k) {
    cameras_[k].push_back({overall_[k].technique, result.scene + "/" + result.camera,
                           result.stats[k], result.seconds[k]});
    overall_[k].stats.merge(result.stats[k]);
    overall_[k].seconds += result.seconds[k];
  }
}

std::vector<OitRow> OitRows::per_camera() const {
  std::vector<OitRow> rows;
  for (const auto& camera : cameras_) rows.insert(rows.end(), camera.begin(), camera.end());
  return rows;
}

OitFrameResult evaluate_oit_frame(const DeepFrame& frame, const std::string& scene,
                                  const std::vector<std::string>& techniques,
                                  const OitParams& params, int threads, const LabConverter& lab,
                                  bool quiet) {
  check_frame_has_transparency(frame, scene);
  const size_t pixels = frame.pixels();
  const FrameReference reference = frame_reference(frame, lab, params.warp, params.depth_range);
  OitFrameResult result;
  result.scene = scene, result.camera = frame.camera;
  result.width = frame.width, result.height = frame.height;
  result.reference = reference.composite;
  ProgressBar bar("oit " + scene + "/" + frame.camera, techniques.size(), quiet);
  std::vector<PixelError> errors(pixels);
  for (const auto& name : techniques) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Rgb> composite(pixels);
    size_t failures = 0;
    run_technique(frame, reference, name, params, threads, lab, composite, errors, failures);
    OitStats stats;
    std::vector<float> delta_e(pixels, -1.0f);
    for (size_t p = 0; p < pixels; ++p) {
      stats.add(errors[p]);
      if (errors[p].fragments) delta_e[p] = float(errors[p].delta_e);
    }
    stats.failures = failures;
    result.composites.push_back(std::move(composite));
    result.delta_e.push_back(std::move(delta_e));
    result.stats.push_back(std::move(stats));
    result.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    bar.advance();
  }
  bar.finish();
  return result;
}

std::string describe_oit_settings(const OitParams& p) {
  return "depth warp: " + std::string(p.warp == WarpKind::Linear ? "linear" : "logarithmic") +
         (p.depth_range == DepthRangeKind::Fragments
              ? " between each camera's nearest and farthest transparent fragment"
              : " over the depth range of the bounding sphere of each scene's transparent "
                "geometry (seed 003)") +
         " (docs/transparency.md §2); " +
         technique_option_text({TechniqueFamily::Transmittance}, p.technique) +
         ", MBOIT's moment bias " + round_trip(p.double_bias.power[0]) +
         " (double; float and 16-bit variants: the authors' code's biases); lp: grid " +
         std::to_string(p.technique.lp.grid) + " on [" + round_trip(p.technique.lp.lo) + ", " +
         round_trip(p.technique.lp.hi) +
         "] of the warped depth and the pixel's fragment depths, "
         "backend " +
         p.technique.lp_backend + ", lp.beta " + round_trip(p.technique.lp_beta);
}

}  // namespace mb
