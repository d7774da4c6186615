#include "verify/verify_run.h"

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

}  // namespace

VerifyPlan make_verify_plan(const VerifySettings& v, const TechniqueParams& technique) {
  VerifyPlan plan;
  plan.settings = v;
  plan.params = verify_params(technique);
  // verify's own values of these rows' options (verify_options.cpp: scales the LP can represent);
  // a value given for the row's option itself would be replaced, so it is refused.
  const TechniqueParams defaults;
  const auto replace = [&](const char* key, double given, double default_value, double value,
                           const char* by) {
    if (given != default_value)
      throw InputError(std::string(key) + ": " + round_trip(given) +
                       "; verify judges this row at " + by + " (" + round_trip(value) +
                       ", a scale the LP represents), expected its default " +
                       round_trip(default_value) + " (set " + by + " instead)");
  };
  replace("esm.c", technique.number("esm.c"), defaults.number("esm.c"), v.esm_c, "verify.esm_c");
  replace("evsm.c_positive", technique.number("evsm.c_positive"),
          defaults.number("evsm.c_positive"), v.evsm_c, "verify.evsm_c");
  replace("csm.terms", technique.integer("csm.terms"), defaults.integer("csm.terms"), v.csm_terms,
          "verify.csm_terms");
  plan.params.set("esm.c", v.esm_c);
  plan.params.set("evsm.c_positive", v.evsm_c);
  plan.params.set("csm.terms", v.csm_terms);
  plan.targets = verify_targets(v.techniques, plan.params);
  for (auto& t : plan.targets) {
    t.storage_box = t.storage_box && v.moment_box != "off";
    t.storage_strict = v.moment_box == "strict";
  }
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

}  // namespace mb
