// Solves the runs lp_runs_dump wrote, warm along each run as lp_bench's SolveRuns/fast_warm rows
// do, and prints one line a row: "<row> <answers> <pivots> <sum of G> <LPs> <not optimal>", the
// answers being a hash of every G's bits. It links the LP engine alone (momentbench_lp), so that
// scripts/check_isa_builds.sh builds only that for other -march targets.
//   lp_replay FILE
#include <bit>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "run_fragments.h"

namespace {

void replay(const mb::bench::FragmentRuns& fragments, const std::string& basis, int grid) {
  const auto runs = mb::bench::build_runs(fragments, {basis}, grid);
  auto backend = mb::lp::make_backend("fast");
  mb::lp::Problem problem;
  mb::lp::Solution solution;
  uint64_t answers = 0, pivots = 0, lps = 0, not_optimal = 0;
  double g_sum = 0;
  for (const auto& run : runs)
    for (size_t i = 0; i < run.problems.size(); ++i) {
      problem = run.problems[i];  // solved from a copy, as the sweep's reused Problem
      backend->solve_into(problem, i > 0 ? &run.positions[i] : nullptr, solution);
      answers = answers * 1099511628211ull ^ std::bit_cast<uint64_t>(solution.G);
      pivots += uint64_t(solution.iterations);
      not_optimal += solution.status != mb::lp::ProblemStatus::Optimal;
      g_sum += solution.G;
      ++lps;
    }
  std::printf("fast_warm_%s_%d %016" PRIx64 " %" PRIu64 " %.17g %" PRIu64 " %" PRIu64 "\n",
              basis.c_str(), grid, answers, pivots, g_sum, lps, not_optimal);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: lp_replay FILE\n");
    return 2;
  }
  try {
    const auto fragments = mb::bench::read_fragment_runs(argv[1]);
    for (int grid : {256, 1024})
      for (const char* basis : {"power4", "trig4"}) replay(fragments, basis, grid);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lp_replay: %s\n", e.what());
    return 1;
  }
  return 0;
}
