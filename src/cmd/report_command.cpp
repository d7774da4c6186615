// `momentbench report`: one or more sweeps' results databases -> report.md (ranked tables,
// reference techniques, the seed paper's findings checked on this data), candidates.csv,
// series.csv, histogram.csv, references.csv, and the Figure 4-style plot of every series.
#include <cstdio>
#include <filesystem>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "report/sweep_report.h"
#include "util/error.h"
#include "util/option_record.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct ReportOptions {
  std::vector<std::string> results;
  bool plot = false;
  int bins = 0;
  std::vector<std::string> allow_different;
};

const std::vector<OptionRecord<ReportOptions>>& report_options() {
  static const std::vector<OptionRecord<ReportOptions>> records{
      {measures_nothing({"bins", OptionType::Integer, "60", "Histogram bins.", 1, 10000}),
       &ReportOptions::bins},
      {measures_nothing(
           {"plot", OptionType::Boolean, "true",
            "Draw histogram.png/pdf with scripts/plot_histogram.py (needs matplotlib)."}),
       &ReportOptions::plot},
      {measures_nothing({"allow_different", OptionType::StringList, "[]",
                         "Measurement options (identity 'measured' in the sweep's table) whose "
                         "values may differ between the series; each series then states its "
                         "own. Any other difference is refused (docs/sweeps.md, \"Identity\")."}),
       &ReportOptions::allow_different},
  };
  return records;
}

int run_report(const CLI::App& command, const CommonOptions& common, const ReportOptions& flags) {
  auto cmd = CommandRun::begin(report_specs(), common, command,
                               {{"--no-plot", "plot", [&] { return YAML::Node(flags.plot); }},
                                {"--bins", "bins", [&] { return YAML::Node(flags.bins); }},
                                {"--allow-different", "allow_different",
                                 [&] { return YAML::Node(flags.allow_different); }}});
  if (!cmd) return 0;
  ReportOptions o = flags;
  read_options(cmd->config(), report_options(), o);
  if (o.results.empty()) throw InputError("report: give one or more results databases");
  if (common.out.empty()) throw InputError("report: --out DIR is required");
  const std::vector<SweepSeries> series =
      load_sweep_series(o.results, {sweep_specs(), o.allow_different});
  StagedOutputDir& out = cmd->out();
  const SweepReportTables tables = sweep_report_tables(series, o.bins);
  write_file_atomically(out / "candidates.csv", tables.candidates_csv);
  write_file_atomically(out / "series.csv", tables.series_csv);
  write_file_atomically(out / "references.csv", tables.references_csv);
  write_file_atomically(out / "histogram.csv", tables.histogram_csv);
  std::string plot_note;
  const SweepErrorAxis axis = sweep_error_axis(main_series(series));
  if (o.plot)
    plot_note = run_plot_script(
        "plot_histogram.py",
        {"--histogram", (out.staging() / "histogram.csv").string(), "--series",
         (out.staging() / "series.csv").string(), "--references",
         (out.staging() / "references.csv").string(), "--candidates",
         (out.staging() / "candidates.csv").string(), "--error", axis.error, "--over", axis.over},
        (out.staging() / "histogram").string(), "candidate histogram", common.quiet);
  const std::string text = sweep_report_markdown(series, plot_note);
  write_file_atomically(out / "report.md", text);
  out.commit();
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace

std::vector<OptionSpec> report_specs() {
  return option_specs(report_options());
}

void register_report_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<ReportOptions>();
  auto common = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand("report",
                                         "Ranked tables, findings, histogram and plot from one or "
                                         "more sweeps (e.g. of 2, 3 and 4 functions)");
  add_common_options(*command, *common);
  command->add_option("results", options->results,
                      "Sweep output directories (or their results.sqlite files)");
  command->add_flag("!--no-plot", options->plot, "= --set plot=false");
  command->add_option("--bins", options->bins, "= --set bins=N")->check(CLI::Range(1, 10000));
  command
      ->add_option("--allow-different", options->allow_different,
                   "= --set allow_different=KEY,...: series may differ in KEY (repeatable)")
      ->allow_extra_args(false)  // one key an occurrence: the databases after it stay positional
      ->delimiter(',');
  command->callback([options, common, command, &action] {
    action = [options, common, command] { return run_report(*command, *common, *options); };
  });
}

}  // namespace mb
