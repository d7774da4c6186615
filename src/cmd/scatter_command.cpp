// `momentbench scatter`: single-scattering techniques x a dataset's light views and cameras ->
// error table (stdout, report.md), errors.csv, final colour, in-scattering and error images per
// light view and camera (docs/scattering.md §4).
#include <cstdio>
#include <filesystem>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "report/scatter_report.h"
#include "scatter/scatter_run.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> scatter_specs() {
  // The dataset's keys without `resolution` (scatter.reference_resolution sets the light maps').
  std::vector<OptionSpec> specs;
  for (auto spec : dataset_option_specs()) {
    if (spec.name == "resolution") continue;
    if (spec.name == "dataset") spec.default_value = "scattering";
    specs.push_back(spec);
  }
  for (auto& s : scatter_run_option_specs()) specs.push_back(s);
  return specs;
}

namespace {

struct ScatterOptions {
  CommonOptions common;
};

int run_scatter_command(const ScatterOptions& options) {
  auto cmd = CommandRun::begin(scatter_specs(), options.common);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  const ScatterRunOptions run = scatter_run_options_from(config);
  const DatasetDesc dataset = load_dataset(config.string("dataset"));
  const std::vector<ScatterScene> scenes = scatter_scenes(dataset);

  StagedOutputDir& out = cmd->out();
  if (run.images) std::filesystem::create_directories(out.staging() / "images");
  std::vector<ScatterRow> overall, per_frame;
  std::vector<std::vector<ScatterRow>> frame_rows(run.techniques.size());  // per technique
  for (const auto& name : run.techniques) overall.push_back({name, "all", "all", "all", {}, 0});
  ScatterReportContext context;
  run_scatter(scenes, run, cmd->threads(), options.common.quiet, [&](const ScatterFrameResult& r) {
    for (size_t k = 0; k < run.techniques.size(); ++k) {
      frame_rows[k].push_back(
          {run.techniques[k], r.scene, r.view, r.camera, r.stats[k], r.seconds[k]});
      overall[k].stats.merge(r.stats[k]);
      overall[k].seconds += r.seconds[k];
    }
    ++context.frames;
    context.epipole_lines.push_back(r.scene + "/" + r.view + "/" + r.camera + ": " +
                                    std::to_string(r.epipole_pixels) + " of " +
                                    std::to_string(size_t(r.width) * r.height));
    if (run.images)
      context.sheets.push_back(write_scatter_images(
          r, run.techniques, run.reference,
          (out.staging() / "images" / (r.scene + "_" + r.view + "_" + r.camera)).string(),
          run.error_scale));
  });
  for (const auto& rows : frame_rows) per_frame.insert(per_frame.end(), rows.begin(), rows.end());

  const RunMetadata& meta = cmd->metadata();
  context.dataset = dataset.name, context.version = meta.version, context.git_sha = meta.git_sha;
  context.compiler = meta.compiler, context.started = meta.started_utc;
  context.threads = cmd->threads();
  context.settings_text = describe_scatter_settings(run);
  context.reference = run.reference;
  context.epipole_degrees = run.epipole_degrees;
  context.pixels = overall.front().stats.pixels;
  context.non_default = config.non_default();
  context.error_scale = run.error_scale;
  const ScatterReport report = render_scatter_report(context, overall, per_frame);
  write_file_atomically(out / "report.md", report.markdown);
  write_file_atomically(out / "errors.csv", report.errors_csv);
  cmd->finish();
  std::fputs(report.table.c_str(), stdout);
  return 0;
}

}  // namespace

void register_scatter_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<ScatterOptions>();
  CLI::App* command = app.add_subcommand(
      "scatter",
      "Evaluate single-scattering techniques (crepuscular rays in a homogeneous medium) against "
      "the exact in-scattering on a dataset's light views and cameras");
  add_common_options(*command, options->common);
  command->callback(
      [options, &action] { action = [options] { return run_scatter_command(*options); }; });
}

}  // namespace mb
