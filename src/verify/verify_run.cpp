#include "verify/verify_run.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/progress.h"

namespace mb {

namespace {

std::vector<int> ascending_grids(const std::vector<int64_t>& sizes) {
  std::vector<int> grids;
  for (const int64_t n : sizes) {
    if (!grids.empty() && n <= grids.back())
      throw InputError("verify.grids: expected ascending grid sizes, got " + std::to_string(n) +
                       " after " + std::to_string(grids.back()));
    grids.push_back(int(n));
  }
  if (grids.empty()) throw InputError("verify.grids: expected at least one grid size");
  return grids;
}

// verify's value of one of its own keys (a number or an integer record of verify_options()).
double verify_value(const VerifySettings& v, const std::string& key) {
  for (const auto& r : verify_options())
    if (r.spec.name == key)
      return std::visit(
          [&](auto member) -> double {
            using T = std::remove_reference_t<decltype(v.*member)>;
            if constexpr (std::is_arithmetic_v<T>)
              return double(v.*member);
            else
              throw std::logic_error(key + ": not a number of verify");
          },
          r.field);
  throw std::logic_error(key + ": no option of verify");
}

// The rows' options verify replaces by its own (their recipes' `replaced`), each once.
std::vector<const VerifyRecipe*> replacing_recipes() {
  std::vector<const VerifyRecipe*> out;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    if (row->verify && row->verify->replaced &&
        std::none_of(out.begin(), out.end(),
                     [&](const VerifyRecipe* r) { return r->replaced == row->verify->replaced; }))
      out.push_back(&*row->verify);
  return out;
}

}  // namespace

VerifyPlan make_verify_plan(const VerifySettings& v, const TechniqueParams& technique) {
  VerifyPlan plan;
  plan.settings = v;
  plan.params = verify_params(technique);
  // verify's own values of these rows' options (verify_options.cpp: scales the LP can represent);
  // a value given for the row's option itself would be replaced, so it is refused.
  const TechniqueParams defaults;
  for (const VerifyRecipe* recipe : replacing_recipes()) {
    const TechniqueOption& o = *recipe->replaced;
    const std::string key = o.spec.name, by = recipe->verify_key;
    const bool whole = o.spec.type == OptionType::Integer;
    const double value = verify_value(v, by);
    const double given = whole ? technique.integer(o) : technique.number(o);
    const double default_value = whole ? defaults.integer(o) : defaults.number(o);
    if (given != default_value)
      throw InputError(key + ": " + round_trip(given) + "; verify judges this row at " + by + " (" +
                       round_trip(value) + ", a scale the LP represents), expected its " +
                       "default " + round_trip(default_value) + " (set " + by + " instead)");
    plan.params.set(o, value);
  }
  plan.targets = verify_targets(v.techniques, plan.params);
  for (auto& t : plan.targets) {
    t.storage_box = t.storage_box && v.moment_box != "off";
    t.storage_strict = v.moment_box == "strict";
  }
  for (const auto& name : v.oit_techniques) check_oit_verify_technique(name);
  plan.grids = ascending_grids(v.grids);
  plan.continuous = v.discretization == "continuous";
  for (const auto& name : v.scatter_techniques) check_scatter_verify_technique(name);
  // A pass over no instances would prove nothing.
  if (v.random == 0 && v.fragments == 0)
    throw InputError(
        "verify.random, verify.fragments: both 0, nothing to verify; give at least one instance");
  return plan;
}

VerifyRun run_verification(const VerifyPlan& plan, const DatasetOptions& data,
                           const EvalSettings& settings, bool quiet) {
  const VerifySettings& v = plan.settings;
  VerifyRun run;
  run.instances = random_verify_instances(v.random, v.seed);
  run.random_count = run.instances.size();
  if (v.fragments > 0) {
    DatasetDesc dataset = load_dataset(data.dataset);
    run.dataset_name = dataset.name;
    auto views = prepare_views(dataset, data.resolution, settings, quiet);
    for (auto& inst : dataset_verify_instances(views, settings, v.fragments, v.seed))
      run.instances.push_back(std::move(inst));
  }
  for (const auto& target : plan.targets) {
    ProgressBar bar("verify " + target.technique, 1, quiet);
    const auto make = [&] { return make_technique(target.technique, plan.params); };
    run.results.push_back(verify_solver(target, make, run.instances, plan.grids, plan.continuous,
                                        v.tolerance, v.worst, settings.threads));
    bar.advance(1);
    bar.finish();
  }
  for (const auto& name : v.oit_techniques)
    run.oit.push_back(verify_mboit(name, v.oit_pixels, v.seed));
  if (!v.scatter_techniques.empty()) {
    const DatasetDesc dataset = load_dataset(v.scatter_dataset);
    run.scatter_dataset = dataset.name;
    const auto frames = scatter_verify_frames(dataset, v.scatter_resolution, v.scatter_rays, v.seed,
                                              settings.threads);
    for (const auto& name : v.scatter_techniques) {
      ProgressBar bar("verify " + name, 2, quiet);
      for (const double beta : {0.0, 1.0}) {
        run.scatter.push_back(verify_scatter_row(name, beta, frames->frames, v.scatter_resolution));
        bar.advance(1);
      }
      bar.finish();
    }
  }
  return run;
}

std::vector<std::string> verify_verdicts(const VerifyRun& run, bool all_passed, bool& passed) {
  std::vector<std::string> lines;
  for (const auto& r : run.results)
    if (!r.passed() && !r.decides_exit())
      lines.push_back("note: " + r.target.technique + " exceeds its storage box (" +
                      std::to_string(r.beyond_tolerance) + " instances, by up to " +
                      format_number(r.largest_excess, "%.3g") + "; " + std::to_string(r.above_lp) +
                      " above an LP witness): reported; verify.moment_box=strict fails it");
  passed = all_passed;
  if (!all_passed)
    for (const auto& r : run.results)
      if (!r.passed() && r.decides_exit())
        lines.push_back(r.target.technique + " disagrees with the LP (" +
                        std::to_string(r.beyond_tolerance) + " beyond tolerance, " +
                        std::to_string(r.above_lp) + " above an LP witness)");
  for (const auto& r : run.oit)
    if (!r.passed()) {
      passed = false;
      lines.push_back(r.technique + " disagrees with the LP (" + std::to_string(r.beyond) + " of " +
                      std::to_string(r.fragments) + " fragments beyond " +
                      format_number(r.tolerance, "%g") + " in T, " + std::to_string(r.lp_failures) +
                      " LP failures)");
    }
  for (const auto& r : run.scatter)
    if (!r.passed()) {
      passed = false;
      lines.push_back(r.technique + " at scatter.beta " + format_number(r.beta, "%g") +
                      " disagrees with " + r.lp_technique + " (" + std::to_string(r.beyond) +
                      " of " + std::to_string(r.compared) + " rays beyond " +
                      format_number(r.tolerance, "%g") + ", " + std::to_string(r.lp_failures) +
                      " LP failures)");
    }
  return lines;
}

}  // namespace mb
