#include "report/render_stats.h"

#include <cstdio>
#include <sstream>

#include "util/number_text.h"

namespace mb {

namespace {

std::string mean_text(double mean_layers) {
  char mean[32];
  std::snprintf(mean, sizeof mean, "%.3f", mean_layers);
  return mean;
}

}  // namespace

std::string render_stats_csv(const std::vector<RenderStatsRow>& rows) {
  std::ostringstream csv;
  csv << "scene,view,resolution,triangles,fragments,receivers,covered_texels,max_layers,mean_"
         "layers,seconds\n";
  for (const RenderStatsRow& r : rows) {
    const LayerStackStats& s = r.stats;
    csv << r.scene << "," << r.view << "," << r.resolution << "," << s.triangles << ","
        << s.fragments << "," << s.receivers << "," << s.covered_texels << "," << s.max_layers
        << "," << round_trip(s.mean_layers) << "," << round_trip(r.seconds) << "\n";
  }
  return csv.str();
}

std::string render_stats_table(const std::vector<RenderStatsRow>& rows) {
  std::ostringstream table;
  table << "| scene | view | resolution | triangles | fragments | receivers | max layers | mean "
           "layers | seconds |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
  for (const RenderStatsRow& r : rows) {
    const LayerStackStats& s = r.stats;
    table << "| " << r.scene << " | " << r.view << " | " << r.resolution << " | " << s.triangles
          << " | " << s.fragments << " | " << s.receivers << " | " << s.max_layers << " | "
          << mean_text(s.mean_layers) << " | " << r.seconds << " |\n";
  }
  return table.str();
}

std::string render_stats_line(const RenderStatsRow& r) {
  const std::string mean = mean_text(r.stats.mean_layers);
  const auto print = [&](char* to, size_t size) {
    return std::snprintf(to, size,
                         "%s/%s: %zu fragments, %zu receivers, max %d layers, mean %s (%.2f s)\n",
                         r.scene.c_str(), r.view.c_str(), r.stats.fragments, r.stats.receivers,
                         r.stats.max_layers, mean.c_str(), r.seconds);
  };
  std::string line(size_t(print(nullptr, 0)), '\0');
  print(line.data(), line.size() + 1);
  return line;
}

}  // namespace mb
