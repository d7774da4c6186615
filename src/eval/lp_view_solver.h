#pragma once
// The one loop that solves a view's receivers as LPs of Problem 1 (docs/reference.md §2-3), shared
// by eval's lp: techniques and the sweep, so the two cannot drift apart (docs/design.md
// §Performance shape): the basis columns of every texel's layer-0 depth once per view, the exact
// skip where F_Z(z_f - delta_f) = 0, warm-start runs cut the same way for any thread count.
#include <cstdint>
#include <vector>

#include "basis/basis.h"
#include "eval/evaluation.h"
#include "lp/problem.h"
#include "util/progress.h"

namespace mb {

struct LpViewAnswers {
  std::vector<double> shadow;  // G per fragment, in fragment order (0 where skipped or failed)
  uint64_t solved = 0, infeasible = 0, unstable = 0;
};

// The fragments of `fragments` that need an LP: F_Z(z_f - delta_f) > 0 (the others have G = 0),
// or all of them when lp.beta > 0 (the maximum G+ may exceed 0 where F_Z does not).
std::vector<uint32_t> fragments_needing_lp(const Fragments& fragments, double lp_beta = 0);

// Solves the LPs of `needs_lp` (ascending fragment indices of `view`) with `factory`'s basis and
// discretisation, the backend of `settings`; failed LPs are counted and shown lit (G = 0). With
// lp.beta > 0 each answer is G + beta (G+ - G), G+ from the maximum's LP (solved cold).
// `runs`: where each warm-start run begins in `needs_lp`, its size appended, each run's fragments
// in texel order (a screen's units); null: bands of kWarmRunRows rows, `needs_lp` ascending.
LpViewAnswers solve_lp_view(const ViewData& view, const std::vector<uint32_t>& needs_lp,
                            const Basis& basis, const lp::ProblemFactory& factory,
                            const EvalSettings& settings, ProgressBar* progress = nullptr,
                            const std::vector<size_t>* runs = nullptr);

}  // namespace mb
