#pragma once
// What `oit` runs (docs/transparency.md §4): its options declared once as records, and every
// technique on one camera's deep frame against the exact composite. The command adds the outputs;
// this is reachable from tests.
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "oit/color_difference.h"
#include "oit/oit_metrics.h"
#include "raster/deep_frame.h"
#include "scene/dataset.h"
#include "techniques/oit/oit_technique.h"
#include "util/option_record.h"

namespace mb {

// Filled from oit_run_options(), where the defaults are written.
struct OitRunOptions {
  std::vector<std::string> techniques;
  bool images = false;
  bool deep_frames = false;
  double delta_e_scale = 0;
};

// The command's own records; the techniques' (oit.*, lp.*) are techniques/oit/oit_options.h's.
const std::vector<OptionRecord<OitRunOptions>>& oit_run_options();

// Every technique on one deep frame: its composite and per-pixel CIEDE2000 (for images) and its
// statistics. Bit-identical for any thread count (each pixel is answered on its own and the sums
// run in pixel order).
struct OitFrameResult {
  std::string scene, camera;
  int width = 0, height = 0;
  std::vector<Rgb> reference;                // the exact composite, per pixel
  std::vector<std::vector<Rgb>> composites;  // per technique, per pixel
  std::vector<std::vector<float>> delta_e;   // per technique, per pixel; -1: no transparency
  std::vector<OitStats> stats;               // per technique
  std::vector<double> seconds;               // per technique, wall clock
};

// One row of `oit`'s tables: a technique on one camera, or on all of them.
struct OitRow {
  std::string technique, camera;  // camera: "<scene>/<camera>", or "all"
  OitStats stats;
  double seconds = 0;
};

// The rows of `oit`'s tables, gathered one camera's result at a time (a frame's composites are
// held one camera at a time).
class OitRows {
 public:
  explicit OitRows(const std::vector<std::string>& techniques);
  void add(const OitFrameResult& result);
  // Each technique over every camera ("all").
  const std::vector<OitRow>& overall() const { return overall_; }
  // Each technique on each camera, technique-major as eval's per-view rows.
  std::vector<OitRow> per_camera() const;

 private:
  std::vector<OitRow> overall_;
  std::vector<std::vector<OitRow>> cameras_;  // per technique
};

// A camera's deep frame and the scene it shows.
struct SceneFrame {
  std::string scene;
  DeepFrame frame;
};
// Every camera of every scene of `dataset`, rendered; InputError when a camera sees no transparent
// geometry or no scene has a camera.
std::vector<SceneFrame> render_dataset_frames(const DatasetDesc& dataset, int threads);

// InputError naming the camera when its frame holds no transparent fragment (nothing to measure;
// the warp would have no range).
void check_frame_has_transparency(const DeepFrame& frame, const std::string& scene);

OitFrameResult evaluate_oit_frame(const DeepFrame& frame, const std::string& scene,
                                  const std::vector<std::string>& techniques,
                                  const OitParams& params, int threads, const LabConverter& lab,
                                  bool quiet);

// The sentence a report states the run's settings in: the warp and its range, MBOIT's beta and
// bias, and the lp: rows' grid, interval, backend and lp.beta.
std::string describe_oit_settings(const OitParams& params);

}  // namespace mb
