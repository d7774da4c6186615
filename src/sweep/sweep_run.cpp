#include "sweep/sweep_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "eval/eval_config.h"
#include "lp/solution.h"
#include "oit/oit_run.h"
#include "scene/dataset_options.h"
#include "sweep/candidate_evaluation.h"
#include "sweep/oit_target.h"
#include "sweep/prepared_target.h"
#include "sweep/results_store.h"
#include "sweep/run_identity.h"
#include "sweep/scatter_target.h"
#include "sweep/screen_reach.h"
#include "sweep/sweep_directory.h"
#include "sweep/sweep_plan.h"
#include "techniques/lp_options.h"
#include "techniques/lp_technique.h"
#include "techniques/oit/oit_options.h"
#include "techniques/registry.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"
#include "util/output_dir.h"
#include "util/progress.h"
#include "util/run_metadata.h"

namespace mb {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The rows of `family` that its command runs by default, then the family's sweep references (the
// LP beside the candidates').
std::string reference_default(TechniqueFamily family) {
  std::string list;
  for (const TechniqueRow* row : family_rows(family))
    if (row->default_run && !row->prefix()) list += (list.empty() ? "" : ", ") + row->name;
  for (const SweepReference& reference : sweep_references(family))
    list += (list.empty() ? "" : ", ") + reference.name;
  return "[" + list + "]";
}

// The catalog, the sample and the reference lists choose which candidates and rows a sweep
// measures, never a row's number (OptionEffect::Selects): a resume and a merge keep them, the
// series of one report may differ in them (2, 3 and 4 functions). `target` changes what is
// measured.
const std::vector<OptionRecord<SweepSettings>>& candidate_options() {
  static const std::vector<OptionRecord<SweepSettings>> records{
      {selects_runs({"catalog", OptionType::StringList, "[]",
                     "Functions to combine (names or expressions); empty = the 37-function catalog "
                     "of docs/reference.md §5."}),
       &SweepSettings::catalog},
      {selects_runs(
           {"combination_size", OptionType::Integer, "4", "Functions per candidate.", 1, 7}),
       &SweepSettings::combination_size},
      {selects_runs({"candidates", OptionType::StringList, "[]",
                     "Explicit candidates, each 'f1; f2; ...'; empty = all (or a sample). With "
                     "`sample`, they join the sample."}),
       &SweepSettings::candidates},
      {selects_runs(
           {"sample", OptionType::Integer, "0",
            "Evaluate a seeded random sample of this many (and the explicit `candidates`); 0 "
            "= all, or only the explicit ones.",
            0, 1e12}),
       &SweepSettings::sample},
      {selects_runs({"sample_seed", OptionType::Integer, "1", "Seed of the sample.", 0, 1e18}),
       &SweepSettings::sample_seed},
      {{"target",
        OptionType::String,
        "shadows",
        "What candidates are measured on (docs/sweeps.md, \"Targets\"): shadows, Problem 1's "
        "G per receiver of a shadow dataset against PCF; transparency, the LP's sharp "
        "absorbance bound per fragment of a transparency dataset's cameras against the exact "
        "transmittance (opacity-weighted, docs/transparency.md §7; `resolution` and the "
        "kernel's keys do not apply); scattering, pss_lp:<candidate> at beta 0 per view ray of "
        "a scattering dataset's light views and cameras against pss_exact (docs/scattering.md "
        "§7; scatter.* apply, `resolution` and the kernel's keys do not).",
        -kInfinity,
        kInfinity,
        {"shadows", "transparency", "scattering"}},
       &SweepSettings::target},
      {selects_runs({"scatter_references", OptionType::StringList,
                     reference_default(TechniqueFamily::Scattering),
                     "target scattering: scattering techniques evaluated once on the same light "
                     "views and cameras against pss_exact, for the report (at scatter.beta)."}),
       &SweepSettings::scatter_references},
      {selects_runs(
           {"oit_references", OptionType::StringList,
            reference_default(TechniqueFamily::Transmittance),
            "target transparency: oit techniques evaluated once on the same frames, for the report "
            "(MBOIT at oit.beta, lp:<basis> at lp.beta)."}),
       &SweepSettings::oit_references},
      {selects_runs({"references", OptionType::StringList,
                     sweep_reference_list(TechniqueFamily::HardShadow),
                     "Techniques evaluated once on the same dataset, for the report."}),
       &SweepSettings::references},
  };
  return records;
}

// The screen chooses which candidates are evaluated exactly (OptionEffect::Selects): an exact
// row's error is the same under any screen, and an estimate carries its own standard error.
const std::vector<OptionRecord<ScreenSettings>>& screen_options() {
  static const std::vector<OptionRecord<ScreenSettings>> records{
      {selects_runs(
           {"screen.fraction", OptionType::Number, "0",
            "Screening: every candidate first on this share of each view's units (a row of 16 "
            "texels, the same for all), with a standard error; 0 = every candidate exactly.",
            0, 1}),
       &ScreenSettings::fraction},
      {selects_runs({"screen.top", OptionType::Integer, "20",
                     "Screening: K. The best K estimates, and every candidate whose interval "
                     "reaches the K-th (screen.sigmas, screen.margin), are evaluated exactly.",
                     1, 1e9}),
       &ScreenSettings::top},
      {selects_runs({"screen.sigmas", OptionType::Number, "3",
                     "Screening: standard errors of a candidate's paired difference from the K-th "
                     "best estimate that still count as reaching it.",
                     0, 100}),
       &ScreenSettings::sigmas},
      {selects_runs({"screen.margin", OptionType::Number, "0",
                     "Screening: mean error (a fraction: 1e-4 = 0.01 pp) by which a candidate's "
                     "interval may miss the K-th best estimate and still be evaluated exactly; "
                     "negative: differences below |margin| are ties.",
                     -1, 1}),
       &ScreenSettings::margin},
      {selects_runs({"screen.refine", OptionType::Number, "0",
                     "Screening: a second sample, this share of the units, for the candidates in "
                     "reach after the first, before any is evaluated exactly; 0 = none.",
                     0, 1}),
       &ScreenSettings::refine},
      {selects_runs({"screen.seed", OptionType::Integer, "1",
                     "Screening: seed of the sampled units.", 0, 1e18}),
       &ScreenSettings::seed},
      // Changes no number and no choice: a candidate screened out that the merge cannot prove
      // out of reach is screened again there (screen/screening.h). 0: a shard keeps its best K's
      // unit errors alone (16 KB a candidate on the default dataset), and the merge screens the
      // near-best again, far cheaper than refining or confirming them.
      {measures_nothing(
           {"screen.keep_sigmas", OptionType::Number, "0",
            "Screening: a shard that has screened its candidates keeps the unit errors only of "
            "its best K and of those within this many paired standard errors of its K-th best "
            "estimate, and of the others what proves them out of reach; the merge screens again "
            "any it cannot prove (docs/sweeps.md, \"Full scale\"). Larger keeps a larger "
            "database and screens fewer again. The confirmation keeps at least screen.sigmas.",
            0, 100}),
       &ScreenSettings::keep_sigmas},
  };
  return records;
}

}  // namespace

// The transmittance family's options (techniques/oit/oit_options.h), every one of them: the MBOIT
// reference rows' overestimation, and the depth warp and its range of the transparency target.
std::vector<OptionSpec> sweep_option_specs() {
  std::vector<OptionSpec> specs = option_specs(candidate_options());
  for (const auto& spec : oit_option_specs()) specs.push_back(spec);
  for (const auto& spec : scatter_sweep_option_specs()) specs.push_back(spec);
  for (auto& s : option_specs(screen_options())) specs.push_back(s);
  return specs;
}

std::vector<OptionSpec> sweep_target_specs(const std::string& target) {
  std::vector<OptionSpec> specs = option_specs(candidate_options());
  for (auto& s : option_specs(screen_options())) specs.push_back(s);
  if (target == "transparency") {
    for (auto& s : oit_option_specs()) specs.push_back(s);
    for (auto& s : lp_option_specs()) specs.push_back(s);
  } else if (target == "scattering") {
    for (auto& s : option_specs(dataset_option_records()))
      if (s.name != "resolution") specs.push_back(s);  // scatter.reference_resolution sets it
    for (auto& s : scatter_sweep_option_specs()) specs.push_back(s);
    // The candidates' LP: the lp.* keys pss_lp reads (its row's family options).
    const TechniqueRow& pss_lp = technique_row("pss_lp:", TechniqueFamily::Scattering);
    for (auto& s : lp_option_specs())
      if (std::find(pss_lp.family_options.begin(), pss_lp.family_options.end(), s.name) !=
          pss_lp.family_options.end())
        specs.push_back(s);
  } else {
    for (auto& s : option_specs(dataset_option_records())) specs.push_back(s);
    for (auto& s : hard_shadow_option_specs()) specs.push_back(s);
  }
  return specs;
}

namespace {

// An option that changes a number of some target but is never read by this one (soft.* or oit.beta
// in a shadow sweep, kernel.* in a transparency sweep) would be accepted and change nothing: a
// value off its default is refused (docs/sweeps.md "Identity").
void refuse_unread_options(const Config& config, const std::string& target) {
  const std::vector<OptionSpec> read = sweep_target_specs(target);
  for (const std::string& line : config.non_default()) {
    const std::string key = line.substr(0, line.find(':'));
    if (key == "dataset") continue;
    const auto is_key = [&](const OptionSpec& spec) { return spec.name == key; };
    const auto declared = std::find_if(config.specs().begin(), config.specs().end(), is_key);
    if (declared == config.specs().end() || declared->effect == OptionEffect::None) continue;
    if (std::none_of(read.begin(), read.end(), is_key))
      throw InputError(key + ": " + line.substr(line.find(':') + 2) + "; a sweep with target " +
                       target +
                       " does not read it, so it would change nothing; expected its "
                       "default " +
                       declared->default_value);
  }
}

}  // namespace

SweepSettings sweep_settings_from(const Config& config, int threads) {
  SweepSettings s;
  s.eval = shadow_settings_from(config, threads);
  const DatasetOptions dataset = dataset_options_from(config);
  s.dataset = dataset.dataset;
  s.resolution = dataset.resolution;
  read_options(config, candidate_options(), s);
  // A transparency sweep may rank MBOIT's blend A- + beta (A+ - A-) of any basis; a shadow sweep
  // ranks the sharp bound (the blend over-darkens, docs/reference.md §2).
  if (s.eval.technique.lp_beta != 0 && s.target == "shadows")
    throw InputError("lp.beta: " + std::to_string(s.eval.technique.lp_beta) +
                     "; a shadow sweep ranks bases by their sharp lower bound, expected 0 (eval "
                     "takes lp.beta > 0; so does a sweep with target transparency)");
  // Problem 1 bounds the hard shadow F_Z(z_f) (docs/reference.md §3); the area light's shadow is
  // no F_Z, and every technique may darken past it (docs/soft-shadows.md §1): ranking bases
  // against it would rank nothing the LP proves.
  if (s.eval.light.angle_deg > 0 && s.target == "shadows")
    throw InputError("light.angle: " + round_trip(s.eval.light.angle_deg) +
                     "; a shadow sweep ranks bases by Problem 1's bound on the hard shadow, not "
                     "an area light's (docs/soft-shadows.md), expected 0 (eval takes light.angle "
                     "> 0)");
  // A sweep's candidates are catalog bases, for which seed 000 prints no transform: refused here
  // rather than every candidate failing (docs/reference.md §8).
  if (s.eval.technique.lp_moment_box.rfind("unorm", 0) == 0 &&
      s.eval.technique.lp_moment_transform == "seed")
    throw InputError(
        "lp.moment_transform: seed exists for power4 and power2 only (seed 000 "
        "§4.3), not for a sweep's candidates; expected canonical or optimized with "
        "lp.moment_box = " +
        s.eval.technique.lp_moment_box);
  read_options(config, screen_options(), s.screen);
  refuse_unread_options(config, s.target);
  s.oit = oit_params_from(config);
  s.scatter = scatter_sweep_options_from(config);
  s.references = s.target == "transparency" ? s.oit_references
                 : s.target == "scattering" ? s.scatter_references
                                            : with_oracle_row(s.references, s.eval.bias);
  s.config_yaml = config.to_yaml();
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::vector<std::pair<std::string, double>> view_errors(const SweepTarget& target,
                                                        const std::vector<ErrorStats>& per_view) {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<std::string> names = target.view_names();
  for (size_t v = 0; v < names.size(); ++v) out.push_back({names[v], per_view[v].mean()});
  return out;
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
  const auto since = Clock::now();
  uint64_t lps = 0;
  for (const uint64_t id : ids) {
    lps += one(id);
    char note[64];
    std::snprintf(note, sizeof note, "%.3g LP/s", lps / std::max(seconds_since(since), 1e-9));
    bar.set_note(note);
    bar.advance();
  }
  bar.finish();
}

// One sweep's state: its plan, views, database and evaluator.
class SweepRun {
 public:
  SweepRun(const SweepSettings& s, const SweepJob& job, const SweepPlan& plan,
           const SweepTarget& target, ResultsStore& store)
      : s_(s), job_(job), plan_(plan), target_(target), store_(store) {}

  void evaluate_references();
  void run(const std::vector<uint64_t>& mine);

 private:
  void log(const char* format, auto... args) const {
    if (!job_.quiet) std::fprintf(stderr, format, args...);
  }
  ResultRow exact_row(uint64_t id, const CandidateResult& result, Clock::time_point start) const;
  void evaluate_exactly(const std::vector<uint64_t>& todo, const char* what);
  void screen_and_confirm(const std::vector<uint64_t>& mine);
  ScreenSample sample_of(int stage, const std::vector<std::vector<double>>& pilot_shadow) const;
  void screen_stage(int stage, const ScreenSample& sample, const std::vector<uint64_t>& ids);
  EstimateRow estimate(int stage, uint64_t id, const ScreenSample& sample) const;
  std::vector<uint64_t> reaching(int stage, const ScreenSample& sample,
                                 const std::vector<uint64_t>& ids);
  void screen_out(int stage, const ScreenSample& sample, const std::vector<uint64_t>& ids,
                  double keep_sigmas);
  void screen_again_unproven(int stage, const ScreenSample& sample,
                             const std::vector<uint64_t>& ids);

  const SweepSettings& s_;
  const SweepJob& job_;
  const SweepPlan& plan_;
  const SweepTarget& target_;
  ResultsStore& store_;
};

// A candidate's committed row from its exact evaluation.
ResultRow SweepRun::exact_row(uint64_t id, const CandidateResult& result,
                              Clock::time_point start) const {
  ResultRow row =
      make_result_row(id, plan_.name(id), result.overall, view_errors(target_, result.per_view));
  row.solved = result.solved;
  row.skipped = result.skipped;
  row.infeasible = result.infeasible;
  row.unstable = result.unstable;
  row.darkening_bound = target_.candidate_darkening_bound();
  row.darkening_reason = target_.candidate_darkening_reason();
  row.seconds = seconds_since(start);
  return row;
}

// Every reference technique once (a resumed sweep keeps those it has).
void SweepRun::evaluate_references() {
  std::set<std::string> have;
  for (const auto& r : store_.references()) have.insert(r.name);
  for (const auto& name : s_.references) {
    if (have.count(name)) continue;
    const auto start = Clock::now();
    const ReferenceResult r = target_.reference(name);
    ResultRow row = make_result_row(0, name, r.overall, view_errors(target_, r.per_view));
    row.unstable = r.overall.failures;
    row.darkening_bound = r.darkening_bound;
    row.darkening_reason = r.darkening_reason;
    row.seconds = seconds_since(start);
    store_.put_reference(row);
  }
}

// Candidates evaluated exactly, one committed row each. A numerically dependent combination is
// recorded with every LP failed, shown lit, and the sweep goes on.
void SweepRun::evaluate_exactly(const std::vector<uint64_t>& todo, const char* what) {
  for_each_candidate(todo, what, job_.quiet, [&](uint64_t id) {
    const auto start = Clock::now();
    CandidateResult result;
    try {
      result = target_.evaluate(Basis::parse(plan_.functions(id)));
    } catch (const InputError& e) {
      log("\ncandidate %llu: %s\n", (unsigned long long)id, e.what());
      result = target_.unanswered();
    }
    store_.put_candidate(exact_row(id, result, start));
    return result.solved + result.infeasible + result.unstable;
  });
}

void SweepRun::run(const std::vector<uint64_t>& mine) {
  if (s_.screen.fraction > 0) return screen_and_confirm(mine);
  const std::vector<uint64_t> todo = not_done(mine, store_.candidate_ids());
  log("sweep: %zu candidates in this shard, %zu done, %zu to go; %llu LPs per candidate\n",
      mine.size(), mine.size() - todo.size(), todo.size(),
      (unsigned long long)target_.lp_fragments());
  evaluate_exactly(todo, "sweep");
}

ScreenSample SweepRun::sample_of(int stage,
                                 const std::vector<std::vector<double>>& pilot_shadow) const {
  return target_.screen_sample(pilot_shadow, stage == 1 ? s_.screen.fraction : s_.screen.refine,
                               s_.screen.seed + uint64_t(stage - 1));
}

// One candidate's estimate at `stage` on `sample`.
EstimateRow SweepRun::estimate(int stage, uint64_t id, const ScreenSample& sample) const {
  const auto start = Clock::now();
  EstimateRow row;
  row.id = id;
  row.stage = stage;
  row.name = plan_.name(id);
  CandidateResult counts;
  try {
    row.run_errors = target_.screen(Basis::parse(plan_.functions(id)), sample, &counts);
  } catch (const InputError& e) {
    // As in the exact sweep: every LP fragment failed, shown lit (G = 0).
    log("\ncandidate %llu: %s\n", (unsigned long long)id, e.what());
    counts = {};
    counts.unstable = sample.sampled_lps();
    row.run_errors = target_.unanswered_unit_errors(sample);
  }
  const ScreenEstimate e = estimate_mean_error(sample, row.run_errors);
  row.mean = e.mean;
  row.se = e.se;
  row.solved = counts.solved;
  row.failed = counts.infeasible + counts.unstable;
  row.seconds = seconds_since(start);
  return row;
}

// Estimates of `ids` at `stage` on `sample`, one committed row each (resumable).
void SweepRun::screen_stage(int stage, const ScreenSample& sample,
                            const std::vector<uint64_t>& ids) {
  const std::vector<uint64_t> todo = not_done(ids, store_.estimate_ids(stage));
  log("sweep: screening stage %d: %zu candidates (%zu done) on %zu of %zu units, %llu of %llu "
      "LPs per candidate\n",
      stage, ids.size(), ids.size() - todo.size(), sample.sampled_runs(), sample.runs(),
      (unsigned long long)sample.sampled_lps(), (unsigned long long)target_.lp_fragments());
  for_each_candidate(todo, stage == 1 ? "screen" : "refine", job_.quiet, [&](uint64_t id) {
    const EstimateRow row = estimate(stage, id, sample);
    store_.put_estimate(row);
    return row.solved + row.failed;
  });
}

// Full scale (docs/sweeps.md, "Full scale"): once this database holds its candidates' estimates at
// `stage`, only those within `keep_sigmas` of the best K keep their unit errors.
void SweepRun::screen_out(int stage, const ScreenSample& sample, const std::vector<uint64_t>& ids,
                          double keep_sigmas) {
  const auto [out, of] =
      screen_out_unreachable(store_, stage, ids, sample, s_.screen.rule(), keep_sigmas);
  if (out > 0)
    log("sweep: stage %d: %zu of %zu estimates keep no unit errors (beyond %g standard errors of "
        "the %d-th best)\n",
        stage, out, of, keep_sigmas, s_.screen.top);
}

// Candidates screened out (by their shard) that this sweep's K-th best does not prove out of
// reach are screened again, keeping their unit errors: the confirmation pairs every one it needs.
void SweepRun::screen_again_unproven(int stage, const ScreenSample& sample,
                                     const std::vector<uint64_t>& of) {
  for (std::vector<uint64_t> ids;
       !(ids = unproven_screened_out(store_, stage, of, sample, s_.screen.rule())).empty();) {
    log("sweep: stage %d: %zu screened-out candidates are screened again (not proven out of "
        "reach of the %d-th best)\n",
        stage, ids.size(), s_.screen.top);
    for_each_candidate(ids, "screen again", job_.quiet, [&](uint64_t id) {
      const EstimateRow row = estimate(stage, id, sample);
      store_.put_estimate(row);
      return row.solved + row.failed;
    });
  }
}

// The candidates of `ids` that reach the best (screen/screening.h), from their estimates at
// `stage`; a candidate screened out counts as proven out of reach once screen_again_unproven has
// screened again those it could not prove.
std::vector<uint64_t> SweepRun::reaching(int stage, const ScreenSample& sample,
                                         const std::vector<uint64_t>& ids) {
  screen_again_unproven(stage, sample, ids);
  // Against this sweep's own K-th best, and never closer than the confirmation's own sigmas: what
  // is dropped now is out of reach by its test (screen/screening.h).
  screen_out(stage, sample, ids, std::max(s_.screen.keep_sigmas, s_.screen.sigmas));
  std::map<uint64_t, EstimateRow> by_id;
  for (auto& e : store_.estimates(stage)) by_id[e.id] = std::move(e);
  std::vector<uint64_t> kept;
  std::vector<std::vector<double>> run_errors;
  for (uint64_t id : ids) {
    EstimateRow& row = by_id.at(id);
    if (row.screened_out) continue;
    if (row.run_errors.size() != sample.sampled_runs())
      throw InputError("candidate " + std::to_string(id) + ": its stage " + std::to_string(stage) +
                       " estimate has " + std::to_string(row.run_errors.size()) +
                       " unit errors, this sample " + std::to_string(sample.sampled_runs()) +
                       ": the database was screened on other views");
    kept.push_back(id);
    run_errors.push_back(std::move(row.run_errors));
  }
  std::vector<uint64_t> out;
  for (size_t c : candidates_to_confirm(sample, run_errors, s_.screen.rule()))
    out.push_back(kept[c]);
  log("sweep: stage %d: %zu of %zu candidates in reach of the %d-th best estimate (margin %g, %g "
      "standard errors)\n",
      stage, out.size(), ids.size(), s_.screen.top, s_.screen.margin, s_.screen.sigmas);
  return out;
}

// Screening (screen/screening.h): every candidate of this shard on the sample, one committed
// estimate each; then, once the database holds every planned candidate's estimate (one shard, or
// the merged shards resumed), the candidates that reach the best K exactly.
void SweepRun::screen_and_confirm(const std::vector<uint64_t>& mine) {
  // The pilot, the catalog's first combination (z; z^2; z^3; z^4 in docs/reference.md §5's),
  // exactly: its run errors are what every candidate's sampled runs are compared with
  // (screen/screening.h). When it is a planned candidate of this shard, its exact row is kept too.
  const uint64_t pilot = 0;
  std::vector<std::vector<double>> pilot_shadow;
  log("sweep: the screen's pilot %s, exactly\n", plan_.name(pilot).c_str());
  const auto start = Clock::now();
  const CandidateResult result =
      target_.evaluate(Basis::parse(plan_.functions(pilot)), &pilot_shadow);
  if (std::binary_search(mine.begin(), mine.end(), pilot) && !store_.candidate_ids().count(pilot))
    store_.put_candidate(exact_row(pilot, result, start));

  const ScreenSample first = sample_of(1, pilot_shadow);
  screen_stage(1, first, mine);
  // The confirmation compares every planned candidate: it waits for all shards.
  if (job_.shards > 1 || store_.estimate_ids(1).size() < plan_.ids.size()) {
    // A shard keeps its best K's unit errors (and those within screen.keep_sigmas): the merge
    // proves the others out of reach or screens them again.
    screen_out(1, first, mine, s_.screen.keep_sigmas);
    log("sweep: screened %zu of %zu planned candidates; the confirmation runs when all are "
        "screened: merge the shards, then `sweep --resume` in the merged directory\n",
        store_.estimate_ids(1).size(), plan_.ids.size());
    return;
  }
  std::vector<uint64_t> ids = reaching(1, first, plan_.ids);
  if (s_.screen.refine > 0) {
    // The candidates in reach again, on a larger sample: cheaper than evaluating them exactly,
    // and its smaller standard errors leave fewer in reach.
    const ScreenSample refine = sample_of(2, pilot_shadow);
    screen_stage(2, refine, ids);
    ids = reaching(2, refine, ids);
  }
  evaluate_exactly(not_done(ids, store_.candidate_ids()), "confirm");
  // The best row is exact: ties left unconfirmed that now rank above the best exact mean are
  // evaluated too (sweep/screen_reach.h). Each round makes them exact and can only lower the best
  // exact mean, so the rounds end.
  for (std::vector<uint64_t> ahead;
       !(ahead = estimates_ahead_of_best_exact(store_, plan_.ids)).empty();) {
    log("sweep: %zu unconfirmed estimates below the best exact mean, evaluated exactly\n",
        ahead.size());
    evaluate_exactly(ahead, "confirm");
  }
}

}  // namespace

void run_sweep(const SweepSettings& s, const SweepJob& job) {
  const SweepPlan plan =
      make_sweep_plan(s.catalog, s.combination_size, s.candidates, s.sample, s.sample_seed);
  check_plan(plan, s.eval.technique);
  if (s.target == "shadows")  // names checked before rendering
    for (const auto& name : s.references) make_technique(name, s.eval.technique);
  const DatasetDesc dataset = load_dataset(s.dataset);
  if (job.out.empty()) throw InputError("--out: a sweep needs an output directory");
  const PreparedTarget prepared = prepare_target(s, dataset, job.quiet);
  // `resolution` 0 keeps the dataset's: the identity holds the maps' size it gave, so that a run
  // at 0 and one naming the same size are one measurement (docs/sweeps.md "Identity").
  const std::string meta_resolution =
      s.target == "shadows" ? map_sizes(prepared.views) : std::string();
  // The output directory is the sweep's state: new unless resuming, then it must match.
  const std::string shard_text = std::to_string(job.shard) + "/" + std::to_string(job.shards);
  // The run's identity: every measurement option's value; the dataset by its name.
  std::map<std::string, std::string> meta = measurement_meta(s.config_yaml, s.specs);
  meta["dataset"] = dataset.name;
  if (!meta_resolution.empty()) meta["resolution"] = meta_resolution;
  meta.insert({{"target", s.target},
               {"git_sha", collect_run_metadata(s.eval.threads, {}).git_sha},
               {"catalog_size", std::to_string(plan.catalog.size())},
               {"combination_size", std::to_string(plan.size)},
               {"planned", std::to_string(plan.ids.size())},
               {"settings", s.target == "transparency" ? describe_transparency(s)
                            : s.target == "scattering"
                                ? "target scattering: pss_lp:<candidate> at beta 0 against "
                                  "pss_exact; " +
                                      describe_scatter_settings(s.scatter)
                                : "shadow maps " + meta_resolution + " texels a side; " +
                                      describe_settings(s.eval)}});
  ResultsStore store = open_sweep_directory(
      job.out, {config_hash(s.config_yaml, s.specs), shard_text, s.config_yaml, s.specs}, meta,
      job.resume, job.force);
  write_file_atomically(job.out / ("run_" + std::to_string(std::time(nullptr)) + ".yaml"),
                        to_yaml(collect_run_metadata(s.eval.threads, job.arguments)));
  SweepRun run(s, job, plan, *prepared.target, store);
  run.evaluate_references();
  run.run(shard_ids(plan, job.shard, job.shards));
  if (!job.quiet)
    std::fprintf(stderr, "sweep: %s complete\n", (job.out / "results.sqlite").c_str());
}

}  // namespace mb
