// `momentbench sweep`: every candidate basis of a catalog by its mean L1 error against PCF, with
// the LP (issue 5). Results go to <out>/results.sqlite one committed candidate at a time, so a
// killed sweep resumes with --resume, losing and repeating nothing.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/candidate_evaluation.h"
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "eval/lp_technique.h"
#include "eval/results_store.h"
#include "eval/sweep_directory.h"
#include "eval/sweep_plan.h"
#include "eval/technique.h"
#include "lp/solution.h"
#include "util/error.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

std::vector<OptionSpec> sweep_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs()) specs.push_back(s);
  specs.push_back({"catalog", OptionType::StringList, "[]",
                   "Functions to combine (names or expressions); empty = the 37-function catalog "
                   "of REFERENCE.md §5."});
  specs.push_back({"combination_size", OptionType::Integer, "4", "Functions per candidate.", 1, 7});
  specs.push_back({"candidates", OptionType::StringList, "[]",
                   "Explicit candidates, each 'f1; f2; ...'; empty = all (or a sample)."});
  specs.push_back({"sample", OptionType::Integer, "0",
                   "Evaluate a seeded random sample of this many; 0 = all.", 0, 1e12});
  specs.push_back({"sample_seed", OptionType::Integer, "1", "Seed of the sample.", 0, 1e18});
  specs.push_back({"references", OptionType::StringList,
                   "[pcf, vsm, esm, hamburger4, hausdorff4, hamburger6, tmsm, lp:power4, lp:trig4]",
                   "Techniques evaluated once on the same dataset, for the report."});
  return specs;
}

namespace {

struct SweepOptions {
  CommonOptions common;
  bool resume = false;
  std::string shard = "1/1";
};

// FNV-1a of the effective config without `threads` (which never changes results): a resume or a
// merge with another hash is refused.
std::string config_hash(const Config& config) {
  std::string yaml = config.to_yaml(), kept;
  size_t start = 0;
  while (start < yaml.size()) {
    size_t end = yaml.find('\n', start);
    if (end == std::string::npos) end = yaml.size();
    std::string line = yaml.substr(start, end - start);
    if (line.rfind("threads:", 0) != 0) kept += line + "\n";
    start = end + 1;
  }
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : kept) h = (h ^ c) * 1099511628211ull;
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "%016llx", (unsigned long long)h);
  return buffer;
}

std::vector<std::pair<std::string, double>> view_errors(const std::vector<ViewData>& views,
                                                        const std::vector<ErrorStats>& per_view) {
  std::vector<std::pair<std::string, double>> out;
  for (size_t v = 0; v < views.size(); ++v)
    out.push_back({views[v].scene + "/" + views[v].view, per_view[v].mean()});
  return out;
}

int run_sweep(const SweepOptions& options) {
  Config config = resolve_config(sweep_specs(), options.common);
  if (options.common.print_config) {
    std::fputs(config.to_yaml().c_str(), stdout);
    return 0;
  }
  const auto [shard, shards] = parse_shard(options.shard);
  const int threads = resolve_thread_count(int(config.integer("threads")));
  EvalSettings settings = shadow_settings_from(config, threads);
  SweepPlan plan =
      make_sweep_plan(config.strings("catalog"), int(config.integer("combination_size")),
                      config.strings("candidates"), uint64_t(config.integer("sample")),
                      uint64_t(config.integer("sample_seed")));
  // Every catalog function on the admissible interval, and the candidates' size against the
  // backend, before any work: a function with a pole would fail every candidate it is in.
  {
    std::vector<BasisFunction> functions;
    for (const auto& name : plan.catalog) functions.push_back(BasisFunction::parse(name));
    Basis(functions).check_admissible(settings.technique.lp.lo, settings.technique.lp.hi);
    lp::check_backend_rows(settings.technique.lp_backend, plan.size, "combination_size");
  }
  const auto references = with_oracle_row(config.strings("references"), settings.bias);
  std::map<std::string, std::pair<double, std::string>>
      darkening;  // Technique::darkening_bound, _reason
  for (const auto& name : references) {
    auto technique = make_technique(name, settings.technique);
    darkening[name] = {technique->darkening_bound(), technique->darkening_reason()};
  }
  DatasetDesc dataset = load_dataset(config.string("dataset"));
  if (options.common.out.empty()) throw InputError("--out: a sweep needs an output directory");

  // Scenes are read and rendered before anything is written: bad input leaves no output.
  auto views =
      prepare_views(dataset, int(config.integer("resolution")), settings, options.common.quiet);
  // The output directory is the sweep's state: new unless resuming, then it must match.
  namespace fs = std::filesystem;
  const fs::path out = options.common.out;
  const std::string hash = config_hash(config),
                    shard_text = std::to_string(shard) + "/" + std::to_string(shards);
  ResultsStore store = open_sweep_directory(out, {hash, shard_text, config.to_yaml()},
                                            {{"dataset", dataset.name},
                                             {"reference", reference_name(settings.bias.reference)},
                                             {"git_sha", collect_run_metadata(threads, {}).git_sha},
                                             {"catalog_size", std::to_string(plan.catalog.size())},
                                             {"combination_size", std::to_string(plan.size)},
                                             {"planned", std::to_string(plan.ids.size())},
                                             {"settings", describe_settings(settings)}},
                                            options.resume, options.common.force);
  write_file_atomically(out / ("run_" + std::to_string(std::time(nullptr)) + ".yaml"),
                        to_yaml(collect_run_metadata(threads, process_arguments())));

  // References first (once; a resumed sweep keeps them).
  std::set<std::string> have;
  for (const auto& r : store.references()) have.insert(r.name);
  for (const auto& name : references) {
    if (have.count(name)) continue;
    auto start = std::chrono::steady_clock::now();
    ErrorStats total;
    std::vector<ErrorStats> per_view;
    for (const auto& view : views) {
      TechniqueResult result = evaluate_technique(view, name, settings, nullptr);
      ErrorStats s;
      s.add_all(view.fragments.pcf, result.shadow);
      s.failures = result.failures;
      total.merge(s);
      per_view.push_back(s);
    }
    ResultRow row = make_result_row(0, name, total, view_errors(views, per_view));
    row.unstable = total.failures;
    std::tie(row.darkening_bound, row.darkening_reason) = darkening[name];
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    store.put_reference(row);
  }

  CandidateEvaluator evaluator(views, settings);
  const auto done = store.candidate_ids();
  std::vector<uint64_t> todo;
  for (uint64_t id : shard_ids(plan, shard, shards))
    if (!done.count(id)) todo.push_back(id);
  if (!options.common.quiet)
    std::fprintf(
        stderr,
        "sweep: %zu candidates in this shard, %zu done, %zu to go; %llu LPs per candidate\n",
        todo.size() + done.size(), done.size(), todo.size(),
        (unsigned long long)evaluator.lp_fragments());
  ProgressBar bar("sweep", todo.size(), options.common.quiet);
  const auto sweep_start = std::chrono::steady_clock::now();
  uint64_t lps = 0;
  for (size_t i = 0; i < todo.size(); ++i) {
    const uint64_t id = todo[i];
    auto start = std::chrono::steady_clock::now();
    CandidateResult result;
    try {
      result = evaluator.evaluate(Basis::parse(plan.functions(id)));
    } catch (const InputError& e) {
      // A numerically dependent combination cannot be solved: recorded with every LP fragment
      // failed (shown lit), flagged in the report, and the sweep goes on.
      if (!options.common.quiet)
        std::fprintf(stderr, "\ncandidate %llu: %s\n", (unsigned long long)id, e.what());
      result.unstable = evaluator.lp_fragments();
      for (const auto& view : views) {
        ErrorStats s;
        s.add_all(view.fragments.pcf, std::vector<double>(view.fragments.size(), 0.0));
        result.overall.merge(s);
        result.per_view.push_back(s);
      }
    }
    ResultRow row =
        make_result_row(id, plan.name(id), result.overall, view_errors(views, result.per_view));
    row.solved = result.solved;
    row.skipped = result.skipped;
    row.infeasible = result.infeasible;
    row.unstable = result.unstable;
    row.darkening_bound = kLpDarkeningBound;
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    store.put_candidate(row);
    lps += result.solved + result.infeasible + result.unstable;
    double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
    char note[64];
    std::snprintf(note, sizeof note, "%.3g LP/s", lps / std::max(elapsed, 1e-9));
    bar.set_note(note);
    bar.advance();
  }
  bar.finish();
  if (!options.common.quiet)
    std::fprintf(stderr, "sweep: %s complete\n", (out / "results.sqlite").c_str());
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
  command->callback([options, &action] { action = [options] { return run_sweep(*options); }; });
}

}  // namespace mb
