// `momentbench eval`: techniques x dataset -> error table (stdout, report.md), errors.csv, one
// error histogram CSV per technique, shadow and error images per view, and under area lights with
// msm_soft, blocker_audit.csv (docs/soft-shadows.md §3).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "camera/camera_views.h"
#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/blocker_audit_run.h"
#include "eval/error_stats.h"
#include "eval/eval_config.h"
#include "eval/eval_run.h"
#include "eval/evaluation.h"
#include "report/blocker_audit_report.h"
#include "report/camera_images.h"
#include "report/darkening.h"
#include "report/eval_report.h"
#include "report/shadow_images.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> eval_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  for (auto& s : option_specs(eval_run_options())) specs.push_back(s);
  return specs;
}

namespace {

struct EvalOptions {
  CommonOptions common;
};

int run_eval(const EvalOptions& options) {
  auto cmd = CommandRun::begin(eval_specs(), options.common);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  const DatasetOptions data = dataset_options_from(config);
  EvalRunOptions run;
  read_options(config, eval_run_options(), run);
  const int threads = cmd->threads();
  EvalSettings settings = shadow_settings_from(config, threads);
  if (run.techniques.empty()) throw InputError("techniques: expected at least one technique");
  const auto techniques = with_oracle_row(run.techniques, settings.bias);
  // Construct every technique once before any work: unknown names fail here, with no output.
  for (const auto& name : techniques) {
    if (const TechniqueRow& row = shadow_row(name); row.check) row.check(name, settings.technique);
    technique_darkening_reason(name, settings);
  }
  DatasetDesc dataset = load_dataset(data.dataset);
  const std::vector<Scene> scenes = build_dataset_scenes(dataset);
  if (run.camera_images) check_dataset_cameras(scenes, dataset);
  StagedOutputDir& out = cmd->out();
  const bool quiet = options.common.quiet;

  auto views = prepare_views(scenes, dataset, data.resolution, settings, quiet);
  const std::string soft_text = describe_area_lights(views, settings.light);
  const auto darkening_reason = darkening_reasons(techniques, settings, views);
  for (const auto& name : techniques)
    if (shadow_row(name).solves_lp)
      check_lp_interval(views, settings.technique.lp.lo, settings.technique.lp.hi);
  std::filesystem::create_directories(out.staging() / "histograms");
  if (run.images) std::filesystem::create_directories(out.staging() / "images");
  const auto write = [&](const std::string& name, const ViewData& view,
                         const std::vector<double>& shadow, bool reference) {
    if (!run.images) return;
    const std::string base =
        (out.staging() / "images" / (view.scene + "_" + view.view + "_")).string();
    write_shadow_images(view, shadow, base + file_stem(name), reference ? 0 : run.error_scale);
  };
  const auto write_images = [&](const std::string& name, const ViewData& view,
                                const std::vector<double>& shadow) {
    write(name, view, shadow, is_view_reference(name, view.soft.angle_deg));
  };
  for (const auto& view : views)
    if (view.soft.angle_deg > 0) write(kAreaLightShadow, view, view.fragments.pcf, true);
  const EvalRows rows = evaluate_techniques(views, techniques, settings, quiet, write_images);
  for (const auto& total : rows.overall)
    write_file_atomically(out / ("histograms/" + file_stem(total.technique) + ".csv"),
                          histogram_csv(total.stats));
  if (run.camera_images)
    evaluate_camera_views(scenes, dataset, views, techniques, data.resolution, settings, quiet,
                          [&](const CameraShadows& camera) {
                            write_camera_images(camera, out.staging() / "cameras", run.error_scale);
                          });

  // A blocker search against its sharp bounds (docs/soft-shadows.md §3).
  std::vector<ViewBlockerAudit> audits;
  if (std::any_of(techniques.begin(), techniques.end(),
                  [](const std::string& name) { return shadow_row(name).audits_blocker; }))
    audits = audit_blocker_searches(views, settings);
  if (!audits.empty()) write_file_atomically(out / "blocker_audit.csv", blocker_audit_csv(audits));

  const RunMetadata& meta = cmd->metadata();
  EvalReportContext context;
  context.dataset = dataset.name, context.version = meta.version, context.git_sha = meta.git_sha;
  context.compiler = meta.compiler, context.started = meta.started_utc, context.threads = threads;
  context.settings_text = describe_settings(settings) + soft_text;
  context.reference = settings.bias.reference;
  context.area_light = !soft_text.empty();
  context.views = views.size();
  for (const auto& v : views) context.receivers += v.fragments.size();
  context.non_default = config.non_default();
  context.images = run.images, context.error_scale = run.error_scale;
  context.sections = blocker_audit_section(audits);
  const EvalReport report =
      render_eval_report(context, rows.overall, rows.per_view, darkening_reason);
  write_file_atomically(out / "report.md", report.markdown);
  write_file_atomically(out / "errors.csv", report.errors_csv);
  write_file_atomically(out / "regions.csv", report.regions_csv);
  if (!report.pcss_csv.empty()) write_file_atomically(out / "pcss_errors.csv", report.pcss_csv);
  cmd->finish();
  std::fputs(report.table.c_str(), stdout);
  return 0;
}

}  // namespace

void register_eval_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* command =
      app.add_subcommand("eval", "Evaluate shadow techniques against PCF on a dataset");
  add_common_options(*command, options->common);
  command->callback([options, &action] { action = [options] { return run_eval(*options); }; });
}

}  // namespace mb
