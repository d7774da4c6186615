// `momentbench sweep`: every candidate basis of a catalog by its mean L1 error against PCF, with
// the LP (issue 5). Results go to <out>/results.sqlite one committed candidate at a time, so a
// killed sweep resumes with --resume, losing and repeating nothing.
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/eval_config.h"
#include "sweep/results_store.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_run.h"
#include "util/error.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> sweep_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  for (auto& s : sweep_option_specs()) specs.push_back(s);
  return specs;
}

namespace {

struct SweepOptions {
  CommonOptions common;
  bool resume = false;
  std::string shard = "1/1";
  double screen = 0;                  // --screen F
  const CLI::App* command = nullptr;  // for apply_flags
};

// `sweep --resume -o DIR` without --config resumes DIR's sweep with DIR's own config.yaml (the
// one --config would read back); --set may still change what measures nothing, e.g. threads
// (docs/sweeps.md, "Full scale").
CommonOptions with_own_config(const SweepOptions& options) {
  CommonOptions common = options.common;
  if (!options.resume || !common.config_file.empty() || common.out.empty()) return common;
  const auto own = std::filesystem::path(common.out) / "config.yaml";
  if (!std::filesystem::is_regular_file(own)) {
    if (!common.sets.empty()) return common;  // a sweep of the defaults and --set, new or resumed
    // Nothing to resume and nothing asked for: a mistyped directory would start a default sweep.
    throw InputError(own.string() +
                     ": not found; `sweep --resume -o DIR` without --config resumes the sweep "
                     "DIR holds with its config.yaml (give --config or --set to start one there)");
  }
  common.config_file = own.string();
  if (!common.quiet) std::fprintf(stderr, "sweep: resuming with %s\n", own.c_str());
  return common;
}

// The shard to run: --shard, or on a resume without it the one DIR's database was started as
// (`sweep --resume -o DIR` continues whatever DIR holds).
std::string shard_of(const SweepOptions& options) {
  const auto db = std::filesystem::path(options.common.out) / "results.sqlite";
  if (options.command->get_option("--shard")->count() > 0 || !options.resume ||
      !std::filesystem::is_regular_file(db))
    return options.shard;
  return ResultsStore::open(db.string()).meta()["shard"];
}

int run_sweep_command(const SweepOptions& options) {
  const CommonOptions common = with_own_config(options);
  auto cmd = CommandRun::begin(
      sweep_specs(), common, *options.command,
      {{"--screen", "screen.fraction", [&] { return YAML::Node(options.screen); }}});
  if (!cmd) return 0;
  SweepJob job;
  std::tie(job.shard, job.shards) = parse_shard(shard_of(options));
  job.out = common.out;
  job.resume = options.resume;
  job.force = common.force;
  job.quiet = common.quiet;
  job.arguments = process_arguments();
  // The sweep stages and commits its own output directory (a killed sweep resumes).
  SweepSettings settings = sweep_settings_from(cmd->config(), cmd->threads());
  settings.specs = sweep_specs();
  run_sweep(settings, job);
  return 0;
}

}  // namespace

void register_sweep_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep", "Evaluate every candidate basis of a catalog with the LP (resumable)");
  add_common_options(*command, options->common);
  command->add_flag("--resume", options->resume,
                    "Continue the sweep in --out, with its config.yaml unless --config is given "
                    "(a different config is refused)");
  command->add_option("--shard", options->shard,
                      "Run shard K of N (K/N): every N-th candidate (--resume: the directory's)");
  command->add_option("--screen", options->screen,
                      "= --set screen.fraction=F: screen, then confirm the best");
  options->command = command;
  command->callback(
      [options, &action] { action = [options] { return run_sweep_command(*options); }; });
}

}  // namespace mb
