#pragma once
// `scatter`'s outputs (docs/scattering.md §4): the error table (stdout and report.md), errors.csv
// with a row per technique, scene, light view and camera and an `all` row per technique, and per
// light view and camera each technique's final colour, in-scattering and error images and a
// contact sheet.
#include <string>
#include <vector>

#include "scatter/scatter_run.h"

namespace mb {

struct ScatterRow {
  std::string technique, scene, view, camera;  // "all" in the overall rows
  ScatterStats stats;
  double seconds = 0;
};

struct ScatterReportContext {
  std::string dataset, version, git_sha, compiler, started, settings_text;
  int threads = 0;
  size_t frames = 0, pixels = 0;
  std::vector<std::string> non_default;
  std::vector<std::string> sheets;  // contact sheets, relative to the report
  double error_scale = 0;
  std::string reference;  // scatter.reference
  double epipole_degrees = 0;
  std::vector<std::string> epipole_lines;  // per light view and camera: "<frame>: N of M"
};

struct ScatterReport {
  std::string table, markdown, errors_csv;
};

ScatterReport render_scatter_report(const ScatterReportContext& context,
                                    const std::vector<ScatterRow>& overall,
                                    const std::vector<ScatterRow>& per_frame);

// `<base>_reference_final.png` and `_inscatter.png`, per technique `<base>_<technique>_final.png`
// (surface radiance attenuated plus I), `_inscatter.png` (I alone) and `_error.png`
// (|I - I_ref| / S_max in false colour up to `scale`, with its colour bar), and `<base>_sheet.png`:
// the reference, then each technique, each column its final colour above its in-scattering above
// its error. One exposure per light view and camera, taken from the reference, so that the
// columns compare. With the frame's rectified map, `<base>_rectified.png`: its normalised depths
// in grey (u, the light rays' distance r, to the right; v, their azimuth, down; white where a
// light ray meets no surface), seed 004 Figure 3 (right). Returns the sheet's file name.
std::string write_scatter_images(const ScatterFrameResult& result,
                                 const std::vector<std::string>& techniques,
                                 const std::string& reference, const std::string& base,
                                 double scale);

}  // namespace mb
