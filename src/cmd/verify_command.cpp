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

namespace mb {

std::vector<OptionSpec> verify_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  specs.push_back(
      {"verify.techniques", OptionType::StringList,
       "[hamburger4, hausdorff4, tmsm, vsm, esm, hamburger6, hamburger4_float, "
       "hamburger4_16bit, tmsm_float, evsm2, evsm4, csm]",
       "Closed forms to check (docs/reference.md §6; EVSM as a lower bound of its basis)."});
  specs.push_back({"verify.random", OptionType::Integer, "2000",
                   "Seeded random distributions (1-8 atoms, mixtures).", 0, 1e8});
  specs.push_back({"verify.fragments", OptionType::Integer, "2000",
                   "Real receiver kernels sampled from the dataset (0: none).", 0, 1e8});
  specs.push_back({"verify.seed", OptionType::Integer, "2015",
                   "Seed of the random instances and the fragment sample.", 0, 1e18});
  specs.push_back({"verify.grids", OptionType::IntegerList, "[256, 1024, 4096]",
                   "LP grid sizes, ascending; the last decides unless the discretization is "
                   "continuous.",
                   2, 1 << 24});
  specs.push_back({"verify.discretization",
                   OptionType::String,
                   "continuous",
                   "continuous: Problem 1 on the whole interval (R for Hamburger and VSM) by the "
                   "exchange method with a certificate decides (docs/reference.md §2); grid: the "
                   "finest grid decides.",
                   0,
                   0,
                   {"continuous", "grid"}});
  specs.push_back({"verify.moment_box",
                   OptionType::String,
                   "storage",
                   "Float32 and 16-bit rows: storage = judged as lower bounds of Problem 1 over "
                   "every distribution on [0, 1] whose stored values lie within the format's "
                   "rounding of theirs (docs/reference.md §2), exceeding it reported; strict = "
                   "exceeding it also fails verify; off = against the exact moments, reported as "
                   "bias.",
                   0,
                   0,
                   {"storage", "strict", "off"}});
  specs.push_back({"verify.tolerance", OptionType::Number, "1e-6",
                   "Largest |G_closed_form - G_LP| beyond the instance's own rounding allowance "
                   "(the first-order effect of moments rounded to double): the closed forms' "
                   "arithmetic at alpha = 0.",
                   0, 1});
  specs.push_back({"verify.esm_c", OptionType::Number, "10",
                   "ESM exponent for verify: with c = 80 the LP cannot resolve E[e^{c(z-1)}] below "
                   "its 1e-9 tolerance.",
                   1e-6, 700});
  specs.push_back(
      {"verify.evsm_c", OptionType::Number, "5",
       "EVSM's positive exponent for verify: with c = 40 its LP columns exp(80 (z - 1)) "
       "vanish below the LP's tolerance over most of [0, 1].",
       1e-6, 300});
  specs.push_back({"verify.csm_terms", OptionType::Integer, "3",
                   "CSM's Fourier terms M for verify: M = 8 gives 16 channels, beyond the LP's 15 "
                   "functions; M <= 3 keeps the fast backend, up to 7 runs on GLPK.",
                   1, 7});
  specs.push_back(
      {"verify.worst", OptionType::Integer, "5", "Worst cases listed per solver.", 0, 1000});
  return specs;
}

namespace {

int run_verify(const CommonOptions& options) {
  Config config = resolve_config(verify_specs(), options);
  if (print_config_if_asked(config, options)) return 0;
  const int threads = resolve_thread_count(int(config.integer("threads")));
  EvalSettings settings = shadow_settings_from(config, threads);
  TechniqueParams params = verify_params(settings.technique);
  params.esm_c = config.number("verify.esm_c");
  params.evsm_c_positive = config.number("verify.evsm_c");
  params.csm_terms = int(config.integer("verify.csm_terms"));
  auto targets = verify_targets(config.strings("verify.techniques"), params);
  const std::string moment_box = config.string("verify.moment_box");
  for (auto& t : targets) {
    t.storage_box = t.storage_box && moment_box != "off";
    t.storage_strict = moment_box == "strict";
  }
  std::vector<int> grids;
  for (const int64_t n : config.integers("verify.grids")) {
    if (!grids.empty() && n <= grids.back())
      throw InputError("verify.grids: expected ascending grid sizes, got " + std::to_string(n) +
                       " after " + std::to_string(grids.back()));
    grids.push_back(int(n));
  }
  if (grids.empty()) throw InputError("verify.grids: expected at least one grid size");
  const double tolerance = config.number("verify.tolerance");
  const bool continuous = config.string("verify.discretization") == "continuous";
  const uint64_t seed = uint64_t(config.integer("verify.seed"));
  // A pass over no instances would prove nothing.
  if (config.integer("verify.random") == 0 && config.integer("verify.fragments") == 0)
    throw InputError(
        "verify.random, verify.fragments: both 0, nothing to verify; give at least one instance");
  StagedOutputDir out(options.out, options.force);

  std::vector<VerifyInstance> instances =
      random_verify_instances(int(config.integer("verify.random")), seed);
  const size_t random_count = instances.size();
  std::string dataset_name = "none";
  if (config.integer("verify.fragments") > 0) {
    DatasetDesc dataset = load_dataset(config.string("dataset"));
    dataset_name = dataset.name;
    auto views = prepare_views(dataset, int(config.integer("resolution")), settings, options.quiet);
    for (auto& inst :
         dataset_verify_instances(views, settings, int(config.integer("verify.fragments")), seed))
      instances.push_back(std::move(inst));
  }

  std::vector<VerifySolverResult> results;
  for (const auto& target : targets) {
    ProgressBar bar("verify " + target.technique, 1, options.quiet);
    results.push_back(verify_solver(
        target, [&] { return make_technique(target.technique, params); }, instances, grids,
        continuous, tolerance, int(config.integer("verify.worst")), threads));
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
  write_file_atomically(out / "config.yaml", config.to_yaml());
  write_file_atomically(out / "run.yaml", to_yaml(meta));
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
