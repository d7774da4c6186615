#pragma once
// The fast simplex's tolerances and limits, each with its reason (docs/reference.md §2).
#include "lp/solution.h"

namespace mb::lp::fast {

// Certified bound on |G - G*| (see certify): the promise, not a setting.
constexpr double kCertifyBound = kCertifiedError;

// The simplex's tolerances and limits, a struct so that tests can vary them
// (make_fast_backend(settings)).
struct SimplexSettings {
  // Tolerances. Weights are probabilities (sum w = 1 is the first row) and the rows are
  // orthonormal, so absolute tolerances are meaningful. By weak duality with sum w = 1, a basis
  // whose reduced costs are >= -eps is within eps of the optimum: the certificate's 1e-11 keeps G
  // two orders inside the promised 1e-9.
  double feasibility_tolerance = 1e-11;  // Harris: x_B >= -tol during iterations
  double optimality_tolerance = 1e-11;   // reduced cost >= -tol counts as optimal
  double pivot_tolerance = 1e-9;         // smallest |u_i| accepted as a pivot
  double phase1_tolerance = 1e-10;       // residual artificial mass that means infeasible
  // Largest |B max(x_B, 0) - rhs| a certificate accepts. The bound's |y| * residual term alone is
  // not enough: it bounds how far G lies *above* the optimum (weak duality), but only a (nearly)
  // feasible x_B bounds it from below, and with y = 0 (every basic point behind z_f) the term
  // vanishes: a basis with a negative weight, clamped, then passed as optimal with G = 0 where the
  // optimum was 0.065 (about one LP in a million of the default dataset's, found by comparing
  // sweeps with different warm-start settings fragment by fragment).
  double certify_residual = 1e-12;
  // And no weight of x_B, refined in double-double, below this: a negative weight is a basis that
  // is not feasible, however small the residual clamping it leaves (|y| reaches 1e9, and a basis
  // whose weights were -1e-13 then moved G by ~1e-7 against another path's; 5 LPs of a power4 sweep
  // of the default dataset). Double-double leaves weights that are exactly zero at ~cond(B) 1e-32,
  // far inside this.
  double negligible_weight = 1e-18;
  // Rank-1 updates between fresh inverses. The updates carry over from LP to LP in a lane's
  // factors, and the certificates refine x_B and y against B itself. 32 instead of 16 (with
  // changed_columns 3 instead of 2): 0.36 instead of 0.46 factorisations an LP on lp_bench's warm
  // runs at grid 256, the same pivots, and the 100 000 random instances' and three sweeps' unstable
  // counts as they were. Only run's retry from scratch, the last resort of ill-conditioned LPs (70
  // pivots on a narrow kernel, |y| ~ 1e6), keeps 16: with 32 that LP stayed unstable
  // (LpFastBackend.NarrowKernelThatExtrasFirstPricingLeftUnstableIsSolved).
  int refactor_interval = 32;
  int careful_refactor_interval = 16;
  int degenerate_before_bland = 24;  // degenerate pivots in a row before Bland's rule
  // Bracket-shift rounds per warm basis: the closest z_f's gets 4k, the others, which succeed less
  // often, 6: on the default dataset that saved 3.1M of 17.6M exchanges for 0.15M more pivots
  // (power4 sweep). 8k for the first cut repairs 102k -> 91k but cost the failing
  // starts more.
  int later_try_rounds = 6;
  int guided_steps = 8;  // certificate-guided steps per LP (solve_phase2)
  int warm_tries = 5;    // warm bases tried before the composite repair
  // update_factors: product-form updates instead of a factorisation for up to this many changed
  // columns (see refactor_interval).
  int changed_columns = 3;
  double hopeless_weight = 10;  // a warm try with a weight below -10 is given up
  // Pivots of one simplex run before it gives up (ProblemStatus::IterationLimit): optimal bases
  // are reached in ~20-40 (measured on dataset fragments); a run past this stalls on an
  // ill-conditioned basis. (Also at most 20 (n + k).)
  int max_iterations = 1000;
};

}  // namespace mb::lp::fast
