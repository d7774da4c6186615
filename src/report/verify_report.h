#pragma once
// The report of `momentbench verify` (docs/reference.md §6): verify.md (the table of every closed
// form against the LP, the worst cases with the `solve` commands that reproduce them), verify.csv
// and worst.csv, from verify_solver's results.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shadow/fragments.h"
#include "verify/verification.h"

namespace mb {

// What the report's header states about the run.
struct VerifyReportContext {
  std::string version, git_sha, started;
  int threads = 0;
  uint64_t seed = 0;
  size_t random_count = 0;  // the first random_count instances are random, the rest real kernels
  std::string dataset;
  BiasParams bias;
  int kernel_radius = 0;
  double tolerance = 0;
  std::vector<int> grids;
};

struct VerifyReport {
  std::string markdown, csv, worst_csv;
  bool all_passed = true;  // every exact solver passed
};

VerifyReport render_verify_report(const VerifyReportContext& c,
                                  std::span<const VerifySolverResult> results,
                                  std::span<const VerifyInstance> instances);

}  // namespace mb
