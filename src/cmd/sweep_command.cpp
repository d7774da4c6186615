// `momentbench sweep`: every candidate basis of a catalog by its mean L1 error against PCF, with
// the LP (issue 5). Results go to <out>/results.sqlite one committed candidate at a time, so a
// killed sweep resumes with --resume, losing and repeating nothing.
#include <tuple>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/eval_config.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_run.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> sweep_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  specs.push_back({"catalog", OptionType::StringList, "[]",
                   "Functions to combine (names or expressions); empty = the 37-function catalog "
                   "of docs/reference.md §5."});
  specs.push_back({"combination_size", OptionType::Integer, "4", "Functions per candidate.", 1, 7});
  specs.push_back({"candidates", OptionType::StringList, "[]",
                   "Explicit candidates, each 'f1; f2; ...'; empty = all (or a sample)."});
  specs.push_back({"sample", OptionType::Integer, "0",
                   "Evaluate a seeded random sample of this many; 0 = all.", 0, 1e12});
  specs.push_back({"sample_seed", OptionType::Integer, "1", "Seed of the sample.", 0, 1e18});
  specs.push_back({"references", OptionType::StringList,
                   "[pcf, vsm, esm, hamburger4, hausdorff4, hamburger6, tmsm, lp:power4, lp:trig4]",
                   "Techniques evaluated once on the same dataset, for the report."});
  specs.push_back({"screen.fraction", OptionType::Number, "0",
                   "Screening: every candidate first on this share of each view's units (8 x 16 "
                   "texels, the same for all), with a standard error; 0 = every candidate exactly.",
                   0, 1});
  specs.push_back({"screen.top", OptionType::Integer, "20",
                   "Screening: K. The best K estimates, and every candidate whose interval "
                   "reaches the K-th (screen.sigmas, screen.margin), are evaluated exactly.",
                   1, 1e9});
  specs.push_back({"screen.sigmas", OptionType::Number, "3",
                   "Screening: standard errors of a candidate's paired difference from the K-th "
                   "best estimate that still count as reaching it.",
                   0, 100});
  specs.push_back({"screen.margin", OptionType::Number, "0",
                   "Screening: mean error (a fraction: 1e-4 = 0.01 pp) by which a candidate's "
                   "interval may miss the K-th best estimate and still be evaluated exactly; "
                   "negative: differences below |margin| are ties.",
                   -1, 1});
  specs.push_back({"screen.refine", OptionType::Number, "0",
                   "Screening: a second sample, this share of the units, for the candidates in "
                   "reach after the first, before any is evaluated exactly; 0 = none.",
                   0, 1});
  specs.push_back(
      {"screen.seed", OptionType::Integer, "1", "Screening: seed of the sampled units.", 0, 1e18});
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

int run_sweep_command(const SweepOptions& options) {
  Config config = resolve_config(sweep_specs(), options.common);
  apply_flags(*options.command, config,
              {{"--screen", "screen.fraction", [&] { return YAML::Node(options.screen); }}});
  if (print_config_if_asked(config, options.common)) return 0;
  SweepJob job;
  std::tie(job.shard, job.shards) = parse_shard(options.shard);
  job.out = options.common.out;
  job.resume = options.resume;
  job.force = options.common.force;
  job.quiet = options.common.quiet;
  job.arguments = process_arguments();
  run_sweep(sweep_settings_from(config, resolve_thread_count(int(config.integer("threads")))), job);
  return 0;
}

}  // namespace

void register_sweep_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep", "Evaluate every candidate basis of a catalog with the LP (resumable)");
  add_common_options(*command, options->common);
  command->add_flag("--resume", options->resume,
                    "Continue the sweep in --out (same config required)");
  command->add_option("--shard", options->shard, "Run shard K of N (K/N): every N-th candidate");
  command->add_option("--screen", options->screen,
                      "= --set screen.fraction=F: screen, then confirm the best");
  options->command = command;
  command->callback(
      [options, &action] { action = [options] { return run_sweep_command(*options); }; });
}

}  // namespace mb
