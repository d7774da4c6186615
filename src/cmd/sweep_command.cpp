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
#include "eval/eval_config.h"
#include "eval/evaluation.h"
#include "lp/solution.h"
#include "sweep/candidate_evaluation.h"
#include "sweep/results_store.h"
#include "sweep/run_identity.h"
#include "sweep/screening.h"
#include "sweep/sweep_directory.h"
#include "sweep/sweep_plan.h"
#include "techniques/lp_technique.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/output_dir.h"
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

std::vector<std::pair<std::string, double>> view_errors(const std::vector<ViewData>& views,
                                                        const std::vector<ErrorStats>& per_view) {
  std::vector<std::pair<std::string, double>> out;
  for (size_t v = 0; v < views.size(); ++v)
    out.push_back({views[v].scene + "/" + views[v].view, per_view[v].mean()});
  return out;
}

// A candidate's committed row from its exact evaluation.
ResultRow exact_row(const SweepPlan& plan, uint64_t id, const CandidateResult& result,
                    const std::vector<ViewData>& views,
                    std::chrono::steady_clock::time_point start) {
  ResultRow row =
      make_result_row(id, plan.name(id), result.overall, view_errors(views, result.per_view));
  row.solved = result.solved;
  row.skipped = result.skipped;
  row.infeasible = result.infeasible;
  row.unstable = result.unstable;
  row.darkening_bound = kLpDarkeningBound;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

// The ids of `ids` not in `done`, in order.
std::vector<uint64_t> not_done(const std::vector<uint64_t>& ids, const std::set<uint64_t>& done) {
  std::vector<uint64_t> out;
  for (uint64_t id : ids)
    if (!done.count(id)) out.push_back(id);
  return out;
}

// Runs `one(id)` (which commits its row and returns the LPs it solved) for every id, under a
// progress bar labelled `what` with the LP rate.
template <class One>
void for_each_candidate(const std::vector<uint64_t>& ids, const char* what, bool quiet, One one) {
  ProgressBar bar(what, ids.size(), quiet);
  const auto since = std::chrono::steady_clock::now();
  uint64_t lps = 0;
  for (const uint64_t id : ids) {
    lps += one(id);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
    char note[64];
    std::snprintf(note, sizeof note, "%.3g LP/s", lps / std::max(elapsed, 1e-9));
    bar.set_note(note);
    bar.advance();
  }
  bar.finish();
}

// Screening (issue 33, eval/screening.h): every candidate of this shard on the sample, one
// committed estimate each; then, once the database holds every planned candidate's estimate (one
// shard, or the merged shards resumed), the candidates that reach the best K exactly.
template <class EvaluateExactly>
void screen_and_confirm(const SweepOptions& options, const Config& config, const SweepPlan& plan,
                        const std::vector<uint64_t>& mine, int shards,
                        const CandidateEvaluator& evaluator, ResultsStore& store,
                        EvaluateExactly& evaluate_exactly) {
  const bool quiet = options.common.quiet;
  // The pilot, the catalog's first combination (z; z^2; z^3; z^4 in docs/reference.md §5's),
  // exactly: its run errors are what every candidate's sampled runs are compared with
  // (screening.h). When it is a planned candidate of this shard, its exact row is kept too.
  const uint64_t pilot = 0;
  std::vector<std::vector<double>> pilot_shadow;
  {
    if (!quiet)
      std::fprintf(stderr, "sweep: the screen's pilot %s, exactly\n", plan.name(pilot).c_str());
    const auto start = std::chrono::steady_clock::now();
    const CandidateResult result =
        evaluator.evaluate(Basis::parse(plan.functions(pilot)), &pilot_shadow);
    if (std::binary_search(mine.begin(), mine.end(), pilot) && !store.candidate_ids().count(pilot))
      store.put_candidate(exact_row(plan, pilot, result, evaluator.views(), start));
  }
  ScreenRule rule;
  rule.top = int(config.integer("screen.top"));
  rule.sigmas = config.number("screen.sigmas");
  rule.margin = config.number("screen.margin");
  const uint64_t seed = uint64_t(config.integer("screen.seed"));
  auto sample_of = [&](int stage) {
    return make_screen_sample(evaluator.views(), evaluator.lp_lists(), pilot_shadow,
                              config.number(stage == 1 ? "screen.fraction" : "screen.refine"),
                              seed + uint64_t(stage - 1));
  };
  // Estimates of `ids` at `stage` on `sample`, one committed row each (resumable).
  auto screen_stage = [&](int stage, const ScreenSample& sample, const std::vector<uint64_t>& ids) {
    const std::vector<uint64_t> todo = not_done(ids, store.estimate_ids(stage));
    if (!quiet)
      std::fprintf(stderr,
                   "sweep: screening stage %d: %zu candidates (%zu done) on %zu of %zu units, "
                   "%llu of %llu LPs per candidate\n",
                   stage, ids.size(), ids.size() - todo.size(), sample.sampled_runs(),
                   sample.runs(), (unsigned long long)sample.sampled_lps(),
                   (unsigned long long)evaluator.lp_fragments());
    for_each_candidate(todo, stage == 1 ? "screen" : "refine", quiet, [&](uint64_t id) {
      const auto start = std::chrono::steady_clock::now();
      EstimateRow row;
      row.id = id;
      row.stage = stage;
      row.name = plan.name(id);
      CandidateResult counts;
      try {
        row.run_errors = evaluator.screen(Basis::parse(plan.functions(id)), sample, &counts);
      } catch (const InputError& e) {
        // As in the exact sweep: every LP fragment failed, shown lit (G = 0).
        if (!quiet)
          std::fprintf(stderr, "\ncandidate %llu: %s\n", (unsigned long long)id, e.what());
        counts = {};
        counts.unstable = sample.sampled_lps();
        row.run_errors = sampled_unit_errors(sample, evaluator.views(), {});
      }
      const ScreenEstimate estimate = estimate_mean_error(sample, row.run_errors);
      row.mean = estimate.mean;
      row.se = estimate.se;
      row.solved = counts.solved;
      row.failed = counts.infeasible + counts.unstable;
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      store.put_estimate(row);
      return row.solved + row.failed;
    });
  };
  // The candidates of `ids` that reach the best (screening.h), from their estimates at `stage`.
  auto reaching = [&](int stage, const ScreenSample& sample, const std::vector<uint64_t>& ids) {
    std::map<uint64_t, std::vector<double>> by_id;
    for (auto& e : store.estimates(stage)) by_id[e.id] = std::move(e.run_errors);
    std::vector<std::vector<double>> run_errors;
    for (uint64_t id : ids) {
      auto& errors = by_id.at(id);
      if (errors.size() != sample.sampled_runs())
        throw InputError("candidate " + std::to_string(id) + ": its stage " +
                         std::to_string(stage) + " estimate has " + std::to_string(errors.size()) +
                         " unit errors, this sample " + std::to_string(sample.sampled_runs()) +
                         ": the database was screened on other views");
      run_errors.push_back(std::move(errors));
    }
    std::vector<uint64_t> out;
    for (size_t c : candidates_to_confirm(sample, run_errors, rule)) out.push_back(ids[c]);
    if (!quiet)
      std::fprintf(stderr,
                   "sweep: stage %d: %zu of %zu candidates in reach of the %d-th best estimate "
                   "(margin %g, %g standard errors)\n",
                   stage, out.size(), ids.size(), rule.top, rule.margin, rule.sigmas);
    return out;
  };

  const ScreenSample first = sample_of(1);
  screen_stage(1, first, mine);
  // The confirmation compares every planned candidate: it waits for all shards.
  if (shards > 1 || store.estimate_ids(1).size() < plan.ids.size()) {
    if (!quiet)
      std::fprintf(stderr,
                   "sweep: screened %zu of %zu planned candidates; the confirmation runs when "
                   "all are screened: merge the shards, then `sweep --resume` in the merged "
                   "directory\n",
                   store.estimate_ids(1).size(), plan.ids.size());
    return;
  }
  std::vector<uint64_t> ids = reaching(1, first, plan.ids);
  if (config.number("screen.refine") > 0) {
    // The candidates in reach again, on a larger sample: cheaper than evaluating them exactly,
    // and its smaller standard errors leave fewer in reach.
    const ScreenSample refine = sample_of(2);
    screen_stage(2, refine, ids);
    ids = reaching(2, refine, ids);
  }
  evaluate_exactly(not_done(ids, store.candidate_ids()), "confirm");
}

int run_sweep(const SweepOptions& options) {
  Config config = resolve_config(sweep_specs(), options.common);
  apply_flags(*options.command, config,
              {{"--screen", "screen.fraction", [&] { return YAML::Node(options.screen); }}});
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
  const std::string hash = config_hash(config.to_yaml()),
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
  // Candidates evaluated exactly, one committed row each (a numerically dependent combination is
  // recorded with every LP failed, shown lit, and the sweep goes on).
  auto evaluate_exactly = [&](const std::vector<uint64_t>& todo, const char* what) {
    for_each_candidate(todo, what, options.common.quiet, [&](uint64_t id) {
      auto start = std::chrono::steady_clock::now();
      CandidateResult result;
      try {
        result = evaluator.evaluate(Basis::parse(plan.functions(id)));
      } catch (const InputError& e) {
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
      store.put_candidate(exact_row(plan, id, result, views, start));
      return result.solved + result.infeasible + result.unstable;
    });
  };
  const std::vector<uint64_t> mine = shard_ids(plan, shard, shards);
  if (config.number("screen.fraction") <= 0) {
    const std::vector<uint64_t> todo = not_done(mine, store.candidate_ids());
    if (!options.common.quiet)
      std::fprintf(
          stderr,
          "sweep: %zu candidates in this shard, %zu done, %zu to go; %llu LPs per candidate\n",
          mine.size(), mine.size() - todo.size(), todo.size(),
          (unsigned long long)evaluator.lp_fragments());
    evaluate_exactly(todo, "sweep");
  } else {
    screen_and_confirm(options, config, plan, mine, shards, evaluator, store, evaluate_exactly);
  }
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
  command->add_option("--screen", options->screen,
                      "= --set screen.fraction=F: screen, then confirm the best");
  options->command = command;
  command->callback([options, &action] { action = [options] { return run_sweep(*options); }; });
}

}  // namespace mb
