#pragma once
// `render`'s statistics of each view's layer stack (docs/user-guide.md, render): stats.csv, the
// Markdown table of stats.md and stdout, and a line per view for stderr.
#include <string>
#include <vector>

#include "raster/layer_stack.h"

namespace mb {

struct RenderStatsRow {
  std::string scene, view;
  int resolution = 0;
  LayerStackStats stats;
  double seconds = 0;  // wall clock of the view's rendering
};

// stats.csv: a row per view, numbers that read back exactly.
std::string render_stats_csv(const std::vector<RenderStatsRow>& rows);
// The Markdown table: mean layers to three decimals.
std::string render_stats_table(const std::vector<RenderStatsRow>& rows);
// "scene/view: N fragments, ...": one view's progress line.
std::string render_stats_line(const RenderStatsRow& row);

}  // namespace mb
