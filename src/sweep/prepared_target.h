#pragma once
// What a sweep measures, prepared before anything is written (bad input leaves no output): the
// target's views, frames or scenes, the target itself, and the settings sentences its database
// states (docs/sweeps.md, "Targets").
#include <memory>
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "oit/oit_run.h"
#include "scatter/scatter_frames.h"
#include "scatter/scatter_run.h"
#include "scene/dataset.h"
#include "sweep/sweep_run.h"
#include "sweep/sweep_target.h"

namespace mb {

// What the sweep measures, rendered before anything is written (bad input leaves no output).
struct PreparedTarget {
  std::vector<ViewData> views;               // shadows
  std::vector<SceneFrame> frames;            // transparency
  std::vector<ScatterScene> scatter_scenes;  // scattering: the scenes its frames point into
  std::vector<ScatterFrame> scatter_frames;
  std::unique_ptr<SweepTarget> target;
};

PreparedTarget prepare_target(const SweepSettings& s, const DatasetDesc& dataset, bool quiet);

// The transparency target's settings sentence (the report's and a resume's "settings").
std::string describe_transparency(const SweepSettings& s);

// The shadow maps' sizes of `views`, as `resolution` is written: "64", or "48, 64" when the
// dataset's views differ.
std::string map_sizes(const std::vector<ViewData>& views);

}  // namespace mb
