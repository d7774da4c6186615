// `render`'s statistics (report/render_stats.h): the CSV reads back exactly, the table rounds the
// mean layer count to three decimals, and the progress line names the view.
#include <gtest/gtest.h>

#include "report/render_stats.h"

namespace mb {
namespace {

RenderStatsRow garden_row() {
  RenderStatsRow row{"garden", "sun", 64, {}, 0.25};
  row.stats.triangles = 12, row.stats.fragments = 900, row.stats.receivers = 800;
  row.stats.covered_texels = 600, row.stats.max_layers = 3, row.stats.mean_layers = 1.5;
  return row;
}

TEST(RenderStats, CsvTableAndLineOfOneView) {
  const std::vector<RenderStatsRow> rows{garden_row()};
  EXPECT_EQ(render_stats_csv(rows),
            "scene,view,resolution,triangles,fragments,receivers,covered_texels,max_layers,mean_"
            "layers,seconds\ngarden,sun,64,12,900,800,600,3,1.5,0.25\n");
  const std::string table = render_stats_table(rows);
  EXPECT_NE(table.find("| garden | sun | 64 | 12 | 900 | 800 | 3 | 1.500 | 0.25 |\n"),
            std::string::npos)
      << table;
  EXPECT_EQ(render_stats_line(rows[0]),
            "garden/sun: 900 fragments, 800 receivers, max 3 layers, mean 1.500 (0.25 s)\n");
}

}  // namespace
}  // namespace mb
