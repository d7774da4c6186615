#pragma once
// What `verify` runs (docs/reference.md §6): its settings checked into a plan before any output
// exists, then every target against the LP on the seeded random instances and the dataset's
// kernels. The command writes the report; this is reachable from tests.
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "oit/oit_verification.h"
#include "scene/dataset_options.h"
#include "verify/scatter_verification.h"
#include "verify/verification.h"
#include "verify/verify_options.h"

namespace mb {

struct VerifyPlan {
  VerifySettings settings;
  TechniqueParams params;  // the shadow settings' technique parameters, as verify runs them
  std::vector<VerifyTarget> targets;
  std::vector<int> grids;  // ascending
  bool continuous = true;  // the continuous interval decides, not the finest grid
};

// InputError naming the key on unknown techniques (of either family), unordered grids or nothing
// to verify.
VerifyPlan make_verify_plan(const VerifySettings& settings, const TechniqueParams& technique);

struct VerifyRun {
  std::vector<VerifyInstance> instances;  // the random ones first
  size_t random_count = 0;
  std::string dataset_name = "none";        // when no dataset kernels were sampled
  std::vector<VerifySolverResult> results;  // one per target, in order
  std::vector<OitVerifyRow> oit;            // one per verify.oit_techniques, in order
  // verify.scatter_techniques at scatter.beta 0 and 1, in order (docs/scattering.md §6).
  std::vector<ScatterVerifyRow> scatter;
  std::string scatter_dataset;
};

VerifyRun run_verification(const VerifyPlan& plan, const DatasetOptions& data,
                           const EvalSettings& settings, bool quiet);

// The lines verify prints to stderr: a note for each target beyond its storage box (reported, not
// failed) and, when a target that decides the exit failed (`all_passed` false, the report's
// verdict) or a transmittance row disagrees, one line each. `passed`: whether verify exits 0.
std::vector<std::string> verify_verdicts(const VerifyRun& run, bool all_passed, bool& passed);

}  // namespace mb
