// `momentbench eval`: techniques x dataset -> error table (stdout, report.md), errors.csv, one
// error histogram CSV per technique, shadow and error images per view (issue 3).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/error_stats.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "report/camera_views.h"
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
  specs.push_back(
      {"techniques", OptionType::StringList,
       "[pcf, vsm, esm, hamburger4, hamburger4_float, hamburger4_16bit, hausdorff4, hamburger6, "
       "tmsm, tmsm_float]",
       "Techniques to evaluate: closed forms, pcf, or lp:<basis> (e.g. lp:power4, lp:trig4)."});
  specs.push_back({"images", OptionType::Boolean, "true",
                   "Write shadow and error images per view and technique."});
  specs.push_back(
      {"camera_images", OptionType::Boolean, "false",
       "For every camera a scene names and each of its light views: the camera's image with each "
       "technique's shadow, its difference from PCF, and one contact sheet (cameras/)."});
  specs.push_back({"error_scale", OptionType::Number, "0.5",
                   "|PCF - G| at the top of the error colour bar.", 1e-6, 1});
  return specs;
}

namespace {

struct EvalOptions {
  CommonOptions common;
};

int run_eval(const EvalOptions& options) {
  Config config = resolve_config(eval_specs(), options.common);
  if (print_config_if_asked(config, options.common)) return 0;
  const int threads = resolve_thread_count(int(config.integer("threads")));
  EvalSettings settings = shadow_settings_from(config, threads);
  if (config.strings("techniques").empty())
    throw InputError("techniques: expected at least one technique");
  const auto techniques = with_oracle_row(config.strings("techniques"), settings.bias);
  // Construct every technique once before any work: unknown names fail here, with no output.
  std::map<std::string, double> darkening_bound;
  std::map<std::string, std::string> darkening_reason;
  for (const auto& name : techniques) {
    auto technique = make_technique(name, settings.technique);
    darkening_bound[name] = technique->darkening_bound();
    darkening_reason[name] = technique->darkening_reason();
  }
  DatasetDesc dataset = load_dataset(config.string("dataset"));
  const std::vector<Scene> scenes = build_dataset_scenes(dataset);
  if (config.boolean("camera_images")) check_dataset_cameras(scenes, dataset);
  StagedOutputDir out(options.common.out, options.common.force);
  const bool quiet = options.common.quiet;

  auto views = prepare_views(scenes, dataset, int(config.integer("resolution")), settings, quiet);
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  std::filesystem::create_directories(out.staging() / "histograms");
  if (config.boolean("images")) std::filesystem::create_directories(out.staging() / "images");

  std::vector<EvalRow> overall, per_view;
  for (const auto& name : techniques) {
    ProgressBar bar(name, receivers, quiet);
    EvalRow total;
    total.technique = name;
    total.scene = "all";
    total.darkening_bound = darkening_bound[name];
    for (const auto& view : views) {
      auto start = std::chrono::steady_clock::now();
      TechniqueResult result = evaluate_technique(view, name, settings, &bar);
      EvalRow row = total;
      row.scene = view.scene;
      row.view = view.view;
      row.stats = ErrorStats();
      row.seconds = 0;
      row.stats.add_all(view.fragments.pcf, result.shadow);
      row.stats.failures = result.failures;
      row.fallbacks = result.fallbacks;
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      total.stats.merge(row.stats);
      total.fallbacks += row.fallbacks;
      total.seconds += row.seconds;
      if (config.boolean("images")) {
        std::string base =
            (out.staging() / "images" / (view.scene + "_" + view.view + "_")).string();
        write_shadow_images(view, result.shadow, base + file_stem(name),
                            name == "pcf" ? 0 : config.number("error_scale"));
      }
      per_view.push_back(std::move(row));
    }
    bar.finish();
    write_file_atomically(out / ("histograms/" + file_stem(name) + ".csv"),
                          histogram_csv(total.stats));
    overall.push_back(std::move(total));
  }

  if (config.boolean("camera_images"))
    write_dataset_camera_views(scenes, dataset, views, techniques,
                               int(config.integer("resolution")), settings,
                               config.number("error_scale"), out.staging() / "cameras", quiet);

  const RunMetadata meta = collect_run_metadata(threads, process_arguments());
  EvalReportContext context;
  context.dataset = dataset.name, context.version = meta.version, context.git_sha = meta.git_sha;
  context.compiler = meta.compiler, context.started = meta.started_utc, context.threads = threads;
  context.settings_text = describe_settings(settings), context.reference = settings.bias.reference;
  context.views = views.size(), context.receivers = receivers;
  context.non_default = config.non_default();
  context.images = config.boolean("images"), context.error_scale = config.number("error_scale");
  const EvalReport report = render_eval_report(context, overall, per_view, darkening_reason);
  write_file_atomically(out / "report.md", report.markdown);
  write_file_atomically(out / "errors.csv", report.errors_csv);
  write_run_record(out, config, meta);
  out.commit();
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
