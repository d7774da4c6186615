// `momentbench render`: dataset -> one deep EXR LayerStack per view, previews and statistics.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "raster/deep_exr.h"
#include "raster/previews.h"
#include "raster/render_view.h"
#include "report/render_stats.h"
#include "scene/dataset.h"
#include "util/error.h"
#include "util/option_record.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

namespace {

struct RenderSettings {
  bool previews = false;  // its record holds the default
};

const std::vector<OptionRecord<RenderSettings>>& render_options() {
  static const std::vector<OptionRecord<RenderSettings>> records{
      {measures_nothing({"previews", OptionType::Boolean, "true",
                         "Write PNG previews (layer-0 depth, layer counts)."}),
       &RenderSettings::previews},
  };
  return records;
}

}  // namespace

std::vector<OptionSpec> render_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : option_specs(render_options())) specs.push_back(s);
  return specs;
}

namespace {

struct RenderOptions {
  CommonOptions common;
};

int run_render(const RenderOptions& options) {
  auto cmd = CommandRun::begin(render_specs(), options.common);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  const DatasetOptions data = dataset_options_from(config);
  RenderSettings render;
  read_options(config, render_options(), render);
  const int threads = cmd->threads();
  DatasetDesc dataset = load_dataset(data.dataset);
  int resolution = data.resolution;
  if (resolution == 0) resolution = dataset.resolution;

  // Parse and build every scene before writing anything: bad input leaves no output behind.
  std::vector<Scene> scenes;
  for (const auto& file : dataset.scene_files) {
    scenes.push_back(build_scene(parse_scene(file)));
    if (resolution > 0)
      for (auto& view : scenes.back().views) view.resolution = resolution;
  }
  StagedOutputDir& out = cmd->out();

  std::vector<RenderStatsRow> rows;
  size_t fragments = 0;
  for (const auto& scene : scenes) {
    std::filesystem::create_directories(out.staging() / scene.name);
    for (const auto& view : scene.views) {
      auto start = std::chrono::steady_clock::now();
      LayerStack stack = render_view(scene, view, threads);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::string base = (out.staging() / scene.name / view.name).string();
      write_deep_exr(stack, base + ".exr");
      if (render.previews) {
        write_depth_preview(stack, base + "_depth.png");
        write_layer_count_preview(stack, base + "_layers.png");
      }
      rows.push_back({scene.name, view.name, view.resolution,
                      compute_stats(stack, scene.mesh.triangles.size()), seconds});
      fragments += rows.back().stats.fragments;
      if (!options.common.quiet) std::fputs(render_stats_line(rows.back()).c_str(), stderr);
    }
  }
  // As eval and verify say of a dataset without receivers: nothing rendered is an error.
  if (fragments == 0)
    throw InputError(dataset.file + ": dataset " + dataset.name +
                     " has nothing to render: no view of any scene rasterizes a fragment (every "
                     "triangle degenerate, or no geometry inside the views)");
  const std::string table = render_stats_table(rows);
  write_file_atomically(out / "stats.csv", render_stats_csv(rows));
  write_file_atomically(out / "stats.md",
                        "# Layer stacks of dataset " + dataset.name + "\n\n" + table);
  cmd->finish();
  std::fputs(table.c_str(), stdout);
  return 0;
}

}  // namespace

void register_render_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "Rasterize a dataset's views into depth-layer stacks (deep EXR)");
  add_common_options(*command, options->common);
  command->callback([options, &action] { action = [options] { return run_render(*options); }; });
}

}  // namespace mb
