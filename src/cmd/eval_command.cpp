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
#include "eval/darkening.h"
#include "eval/error_stats.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "eval/shadow_images.h"
#include "eval/technique.h"
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
  specs.push_back({"error_scale", OptionType::Number, "0.5",
                   "|PCF - G| at the top of the error colour bar.", 1e-6, 1});
  return specs;
}

namespace {

struct EvalOptions {
  CommonOptions common;
};

// Technique names may hold ';', ':' and spaces (lp:z;z^2): file names keep [A-Za-z0-9._-].
std::string file_stem(const std::string& name) {
  std::string out;
  for (char c : name)
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

std::string number(double v) {
  return round_trip(v);
}

struct Row {
  std::string technique, scene, view;
  ErrorStats stats;
  double seconds = 0;
  double darkening_bound = 0;  // Technique::darkening_bound
};

std::string table_row(const Row& r) {
  std::ostringstream s;
  s << "| " << r.technique << " | " << r.scene << (r.view.empty() ? "" : "/" + r.view) << " | "
    << r.stats.count << " | " << percent_text(r.stats.mean()) << " | "
    << percent_text(r.stats.leak()) << " | "
    << darkening_text(r.stats.dark(), r.stats.max_dark, r.darkening_bound) << " | "
    << format_number(r.stats.max, "%.6g") << " | " << percent_text(r.stats.share_over_tenth())
    << " | " << r.stats.failures << " |";
  return s.str();
}

int run_eval(const EvalOptions& options) {
  Config config = resolve_config(eval_specs(), options.common);
  if (options.common.print_config) {
    std::fputs(config.to_yaml().c_str(), stdout);
    return 0;
  }
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
  StagedOutputDir out(options.common.out, options.common.force);
  const bool quiet = options.common.quiet;

  auto views = prepare_views(dataset, int(config.integer("resolution")), settings, quiet);
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  std::filesystem::create_directories(out.staging() / "histograms");
  if (config.boolean("images")) std::filesystem::create_directories(out.staging() / "images");

  std::vector<Row> overall, per_view;
  for (const auto& name : techniques) {
    ProgressBar bar(name, receivers, quiet);
    Row total;
    total.technique = name;
    total.scene = "all";
    total.darkening_bound = darkening_bound[name];
    for (const auto& view : views) {
      auto start = std::chrono::steady_clock::now();
      TechniqueResult result = evaluate_technique(view, name, settings, &bar);
      Row row = total;
      row.scene = view.scene;
      row.view = view.view;
      row.stats = ErrorStats();
      row.seconds = 0;
      row.stats.add_all(view.fragments.pcf, result.shadow);
      row.stats.failures = result.failures;
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      total.stats.merge(row.stats);
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
    std::ostringstream histogram;
    histogram << "error_lo,error_hi,fragments\n";
    for (int b = 0; b < ErrorStats::kHistogramBins; ++b)
      histogram << number(double(b) / ErrorStats::kHistogramBins) << ","
                << number(double(b + 1) / ErrorStats::kHistogramBins) << ","
                << total.stats.histogram[b] << "\n";
    write_file_atomically(out / ("histograms/" + file_stem(name) + ".csv"), histogram.str());
    overall.push_back(std::move(total));
  }

  RunMetadata meta = collect_run_metadata(threads, process_arguments());
  const std::string header =
      "| technique | views | receivers | mean error % | leak % | over-darkening % | max error | "
      "share > 0.1 % | "
      "failures |\n|---|---|---|---|---|---|---|---|---|\n";
  std::ostringstream table, report, csv;
  table << header;
  for (const auto& r : overall) table << table_row(r) << "\n";
  report << "# Shadow evaluation of dataset " << dataset.name << "\n\n"
         << "Made by momentbench " << meta.version << " (git " << meta.git_sha << "), "
         << meta.compiler << ", " << threads << " threads, " << meta.started_utc << ".\n\n"
         << "- " << describe_settings(settings) << "\n"
         << "- " << views.size() << " views, " << receivers
         << " receiver fragments (every light-facing fragment of "
         << "every layer, REFERENCE.md §3)\n";
  for (const auto& line : config.non_default()) report << "- option " << line << "\n";
  report << "\n" << protocol_text(settings.bias.reference) << "\n\n";
  for (const auto& r : overall)
    if (r.technique == "oracle" && settings.bias.reference == Reference::ReceiverPlane)
      report << "**Oracle floor: " << percent_text(r.stats.mean())
             << " %.** The error of F_Z(z_f - delta_f) itself against the receiver-plane "
                "reference: the part of every "
                "technique's error that is the bias's, not the moments'.\n\n";
  std::vector<DarkeningRow> darkening;
  for (const auto& r : overall)
    darkening.push_back({r.technique, r.stats.dark(), r.stats.max_dark, r.darkening_bound,
                         darkening_reason[r.technique]});
  report << darkening_notes(darkening) << "## All views\n\n"
         << table.str() << "\n## Per view\n\n"
         << header;
  for (const auto& r : per_view) report << table_row(r) << "\n";
  for (const auto& r : overall)
    if (r.stats.failures)
      report << "\n**" << r.technique << "**: " << r.stats.failures
             << " fragments failed; raise the technique's alpha, or the LP grid, and re-run.\n";
  if (config.boolean("images"))
    report << "\nImages (images/): `<scene>_<view>_<technique>_shadow.exr` holds G of layer-0 "
              "receivers, the PNG shows "
              "1 - G (white = lit; dark blue = no layer-0 receiver); `_error.png` shows |PCF - G| "
              "on a colour bar from "
              "0 to "
           << number(config.number("error_scale")) << ".\n";
  csv << "technique,scene,view,receivers,mean_error,leak,over_darkening,max_over_darkening,max_"
         "error,share_over_0.1,"
         "failures,reference\n";
  for (const auto* rows : {&overall, &per_view})
    for (const auto& r : *rows)
      csv << '"' << r.technique << "\"," << r.scene << "," << (r.view.empty() ? "all" : r.view)
          << "," << r.stats.count << "," << number(r.stats.mean()) << "," << number(r.stats.leak())
          << "," << number(r.stats.dark()) << "," << number(r.stats.max_dark) << ","
          << number(r.stats.max) << "," << number(r.stats.share_over_tenth()) << ","
          << r.stats.failures << "," << reference_name(settings.bias.reference) << "\n";
  write_file_atomically(out / "report.md", report.str());
  write_file_atomically(out / "errors.csv", csv.str());
  write_file_atomically(out / "config.yaml", config.to_yaml());
  write_file_atomically(out / "run.yaml", to_yaml(meta));
  out.commit();
  std::fputs(table.str().c_str(), stdout);
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
