// `momentbench oit`: transparency techniques x a dataset's cameras -> error table (stdout,
// report.md), errors.csv, composites and their CIEDE2000 differences per camera, deep frames
// (docs/transparency.md §4).
#include <cstdio>
#include <filesystem>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "oit/deep_frame_exr.h"
#include "oit/oit_run.h"
#include "report/eval_report.h"
#include "report/oit_report.h"
#include "techniques/lp_options.h"
#include "techniques/oit/oit_options.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> oit_specs() {
  // The dataset's keys without `resolution` (a light view's; cameras carry their own).
  std::vector<OptionSpec> specs;
  for (auto spec : dataset_option_specs()) {
    if (spec.name == "resolution") continue;
    if (spec.name == "dataset") spec.default_value = "transparency";
    specs.push_back(spec);
  }
  // The transmittance family's options right after the techniques they set.
  for (auto& s : option_specs(oit_run_options())) {
    specs.push_back(s);
    if (s.name == "techniques")
      for (auto& o : oit_option_specs()) specs.push_back(o);
  }
  for (auto& s : lp_option_specs()) specs.push_back(s);
  return specs;
}

namespace {

struct OitOptions {
  CommonOptions common;
};

int run_oit(const OitOptions& options) {
  auto cmd = CommandRun::begin(oit_specs(), options.common);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  OitRunOptions run;
  read_options(config, oit_run_options(), run);
  const int threads = cmd->threads();
  const OitParams params = oit_params_from(config);
  if (run.techniques.empty()) throw InputError("techniques: expected at least one technique");
  for (const auto& name : run.techniques) make_oit_technique(name, params);  // names fail here
  const DatasetDesc dataset = load_dataset(config.string("dataset"));
  const std::vector<SceneFrame> frames = render_dataset_frames(dataset, threads);

  StagedOutputDir& out = cmd->out();
  if (run.images) std::filesystem::create_directories(out.staging() / "images");
  if (run.deep_frames) std::filesystem::create_directories(out.staging() / "frames");
  const LabConverter lab;
  OitRows rows(run.techniques);
  OitReportContext context;
  for (const auto& [scene, frame] : frames) {
    const std::string stem = scene + "_" + frame.camera;
    if (run.deep_frames)
      write_deep_frame_exr(frame, scene, (out.staging() / "frames" / (stem + ".exr")).string());
    const OitFrameResult result = evaluate_oit_frame(frame, scene, run.techniques, params, threads,
                                                     lab, options.common.quiet);
    rows.add(result);
    if (run.images)
      context.sheets.push_back(write_oit_images(
          result, run.techniques, (out.staging() / "images" / stem).string(), run.delta_e_scale));
  }
  const RunMetadata& meta = cmd->metadata();
  context.dataset = dataset.name, context.version = meta.version, context.git_sha = meta.git_sha;
  context.compiler = meta.compiler, context.started = meta.started_utc, context.threads = threads;
  context.settings_text = describe_oit_settings(params);
  context.cameras = frames.size();
  context.fragments = rows.overall().front().stats.fragments;
  context.pixels = rows.overall().front().stats.pixels;
  context.non_default = config.non_default();
  context.delta_e_scale = run.delta_e_scale;
  const OitReport report = render_oit_report(context, rows.overall(), rows.per_camera());
  write_file_atomically(out / "report.md", report.markdown);
  write_file_atomically(out / "errors.csv", report.errors_csv);
  cmd->finish();
  std::fputs(report.table.c_str(), stdout);
  return 0;
}

}  // namespace

void register_oit_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<OitOptions>();
  CLI::App* command = app.add_subcommand(
      "oit",
      "Evaluate order-independent transparency techniques against exact compositing on a "
      "dataset's cameras");
  add_common_options(*command, options->common);
  command->callback([options, &action] { action = [options] { return run_oit(*options); }; });
}

}  // namespace mb
