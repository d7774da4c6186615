// `momentbench verify` (docs/reference.md §6): each closed form against the LP with the matching
// basis and interval, on seeded random distributions and on real kernels of a dataset, at three
// LP grid sizes. Exit status 5 when a solver that must match (double, alpha = 0) does not.
#include <cstdio>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "report/oit_report.h"
#include "report/scatter_verify_report.h"
#include "report/verify_report.h"
#include "scene/dataset.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"
#include "verify/verify_run.h"

namespace mb {

std::vector<OptionSpec> verify_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : hard_shadow_option_specs()) specs.push_back(s);
  for (auto& s : option_specs(verify_options())) specs.push_back(s);
  return specs;
}

namespace {

int run_verify(const CommonOptions& options) {
  auto cmd = CommandRun::begin(verify_specs(), options);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  const DatasetOptions data = dataset_options_from(config);
  const int threads = cmd->threads();
  const EvalSettings settings = shadow_settings_from(config, threads);
  VerifySettings v;
  read_options(config, verify_options(), v);
  const VerifyPlan plan = make_verify_plan(v, settings.technique);
  StagedOutputDir& out = cmd->out();
  const VerifyRun run = run_verification(plan, data, settings, options.quiet);

  const RunMetadata& meta = cmd->metadata();
  VerifyReportContext context;
  context.version = meta.version, context.git_sha = meta.git_sha,
  context.started = meta.started_utc;
  context.threads = threads, context.seed = v.seed, context.random_count = run.random_count;
  context.dataset = run.dataset_name, context.bias = settings.bias;
  context.kernel_radius = settings.kernel.radius(), context.tolerance = v.tolerance;
  context.grids = plan.grids;
  if (plan.continuous) context.grids.push_back(0);
  const VerifyReport report = render_verify_report(context, run.results, run.instances);
  const std::string scatter_section =
      scatter_verify_section(run.scatter, run.scatter_dataset, v.scatter_resolution);
  write_file_atomically(out / "verify.md",
                        report.markdown + oit_verify_section(run.oit) + scatter_section);
  if (!run.oit.empty()) write_file_atomically(out / "verify_oit.csv", oit_verify_csv(run.oit));
  if (!run.scatter.empty())
    write_file_atomically(out / "verify_scatter.csv", scatter_verify_csv(run.scatter));
  write_file_atomically(out / "verify.csv", report.csv);
  write_file_atomically(out / "worst.csv", report.worst_csv);
  cmd->finish();
  // The table on stdout.
  const std::string& text = report.markdown;
  std::fputs(text.substr(0, text.find("\n## Worst")).c_str(), stdout);
  std::fputs("\n", stdout);
  std::fputs(oit_verify_section(run.oit).c_str(), stdout);
  std::fputs(scatter_section.c_str(), stdout);
  bool passed = true;
  for (const auto& line : verify_verdicts(run, report.all_passed, passed))
    std::fprintf(stderr, "momentbench: verify: %s\n", line.c_str());
  return passed ? 0 : 5;
}

}  // namespace

void register_verify_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command =
      app.add_subcommand("verify", "Check every closed-form solver against the LP ground truth");
  add_common_options(*command, *options);
  command->callback([options, &action] { action = [options] { return run_verify(*options); }; });
}

}  // namespace mb
