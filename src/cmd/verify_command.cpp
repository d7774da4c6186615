// `momentbench verify` (docs/reference.md §6): each closed form against the LP with the matching
// basis and interval, on seeded random distributions and on real kernels of a dataset, at three
// LP grid sizes. Exit status 5 when a solver that must match (double, alpha = 0) does not.
#include <cstdio>
#include <sstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/error_stats.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "report/verify_report.h"
#include "scene/dataset.h"
#include "scene/procedural.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/progress.h"
#include "util/run_metadata.h"
#include "verify/verification.h"
#include "verify/verify_options.h"

namespace mb {

std::vector<OptionSpec> verify_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  for (auto& s : option_specs(verify_options())) specs.push_back(s);
  return specs;
}

namespace {

int run_verify(const CommonOptions& options) {
  Config config = resolve_config(verify_specs(), options);
  if (print_config_if_asked(config, options)) return 0;
  const int threads = resolve_thread_count(int(config.integer("threads")));
  EvalSettings settings = shadow_settings_from(config, threads);
  TechniqueParams params = verify_params(settings.technique);
  VerifySettings v;
  read_options(config, verify_options(), v);
  params.esm_c = v.esm_c;
  params.evsm_c_positive = v.evsm_c;
  params.csm_terms = v.csm_terms;
  auto targets = verify_targets(v.techniques, params);
  const std::string& moment_box = v.moment_box;
  for (auto& t : targets) {
    t.storage_box = t.storage_box && moment_box != "off";
    t.storage_strict = moment_box == "strict";
  }
  std::vector<int> grids;
  for (const int64_t n : v.grids) {
    if (!grids.empty() && n <= grids.back())
      throw InputError("verify.grids: expected ascending grid sizes, got " + std::to_string(n) +
                       " after " + std::to_string(grids.back()));
    grids.push_back(int(n));
  }
  if (grids.empty()) throw InputError("verify.grids: expected at least one grid size");
  const double tolerance = v.tolerance;
  const bool continuous = v.discretization == "continuous";
  const uint64_t seed = v.seed;
  // A pass over no instances would prove nothing.
  if (v.random == 0 && v.fragments == 0)
    throw InputError(
        "verify.random, verify.fragments: both 0, nothing to verify; give at least one instance");
  StagedOutputDir out(options.out, options.force);

  std::vector<VerifyInstance> instances = random_verify_instances(v.random, seed);
  const size_t random_count = instances.size();
  std::string dataset_name = "none";
  if (v.fragments > 0) {
    DatasetDesc dataset = load_dataset(config.string("dataset"));
    dataset_name = dataset.name;
    auto views = prepare_views(dataset, int(config.integer("resolution")), settings, options.quiet);
    for (auto& inst : dataset_verify_instances(views, settings, v.fragments, seed))
      instances.push_back(std::move(inst));
  }

  std::vector<VerifySolverResult> results;
  for (const auto& target : targets) {
    ProgressBar bar("verify " + target.technique, 1, options.quiet);
    results.push_back(verify_solver(
        target, [&] { return make_technique(target.technique, params); }, instances, grids,
        continuous, tolerance, v.worst, threads));
    bar.advance(1);
    bar.finish();
  }

  const RunMetadata meta = collect_run_metadata(threads, process_arguments());
  VerifyReportContext context;
  context.version = meta.version, context.git_sha = meta.git_sha,
  context.started = meta.started_utc;
  context.threads = threads, context.seed = seed, context.random_count = random_count;
  context.dataset = dataset_name, context.bias = settings.bias;
  context.kernel_radius = settings.kernel.radius(), context.tolerance = tolerance;
  context.grids = grids;
  if (continuous) context.grids.push_back(0);
  const VerifyReport report = render_verify_report(context, results, instances);
  write_file_atomically(out / "verify.md", report.markdown);
  write_file_atomically(out / "verify.csv", report.csv);
  write_file_atomically(out / "worst.csv", report.worst_csv);
  write_run_record(out, config, meta);
  out.commit();
  // The table on stdout.
  const std::string& text = report.markdown;
  std::fputs(text.substr(0, text.find("\n## Worst")).c_str(), stdout);
  std::fputs("\n", stdout);
  for (const auto& r : results)
    if (!r.passed() && !r.decides_exit())
      std::fprintf(stderr,
                   "momentbench: verify: note: %s exceeds its storage box (%zu instances, by up to "
                   "%.3g; %zu above an LP witness): reported; verify.moment_box=strict fails it\n",
                   r.target.technique.c_str(), r.beyond_tolerance, r.largest_excess, r.above_lp);
  if (!report.all_passed) {
    for (const auto& r : results)
      if (!r.passed() && r.decides_exit())
        std::fprintf(stderr,
                     "momentbench: verify: %s disagrees with the LP (%zu beyond tolerance, %zu "
                     "above an LP witness)\n",
                     r.target.technique.c_str(), r.beyond_tolerance, r.above_lp);
    return 5;
  }
  return 0;
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
