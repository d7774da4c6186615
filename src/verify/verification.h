#pragma once
// `momentbench verify` (docs/reference.md §6): every closed form against the LP with the matching
// basis and interval, on seeded random depth distributions and on real kernels of a dataset, at
// several LP grid sizes.
#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "techniques/technique.h"

namespace mb {

// One row of docs/reference.md §6: a closed form and its LP ground truth.
struct VerifyTarget {
  std::string technique;
  std::vector<std::string> lp_basis;
  double lo = 0, hi = 1;  // the LP's admissible interval
  bool exact = false;     // double precision, alpha = 0: must match; otherwise reported only
  // A valid lower bound that is not the sharp one (EVSM, seed 000 §2): it passes when it never
  // exceeds the LP on the finest grid (itself never below the sharp bound of the continuous
  // problem) nor an LP witness; |dG| is reported, not judged.
  bool lower_bound = false;
  // VSM on R: Cantelli's extremal support for the instance's distribution and z_f joins the LP's
  // points (within ten interval widths), so that an LP on a bounded interval can represent it
  // where it lies beyond the interval (docs/reference.md §6).
  bool cantelli_support = false;
  // Problem 1 on all of R (Hamburger, VSM): the continuous ground truth uses I = R; [lo, hi]
  // bounds the grid LPs only.
  bool on_r = false;
  // Float32 and 16-bit rows: the ground truth is Problem 1 over every distribution whose stored
  // values lie in the storage format's box (docs/reference.md §2, "Moments with a tolerance";
  // moments/storage.h), solved on the continuous interval, and the closed form must not exceed it
  // by more than its bias alpha (the biased moments are a mixture's, see techniques/closed_form.h)
  // plus 1e-6. Without the continuous ground truth such a row is reported, not judged.
  bool storage_box = false;
  double alpha = 0;  // the technique's moment bias
  // Whether exceeding the box fails verify (verify.moment_box = strict). By default it is
  // reported: seed 000 §4.3 reports quantization noise at these alphas, so a storage variant
  // above its box is the method's property at that alpha, not a wrong closed form.
  bool storage_strict = false;
  // Not a lower bound (CSM: a truncated Fourier series rings): reported is how often
  // (above_finest) and by how much (largest_excess) it exceeds the sharp bound of its basis.
  bool exceedance = false;
  // Hamburger's rows (power4, power6 on R): also the upper bound G + w_1 of the canonical
  // distribution through z_f (seed 004's beta = 1) against the LP's maximum (docs/reference.md §2).
  bool upper = false;
  int hamburger_moments = 0;  // VerifyRecipe::hamburger_moments
  // Whether the upper comparison decides the verdict (both rows).
  bool upper_judged = false;
  // Six power moments on R: judged over their double rounding box (verify/rounding_box.h), i.e.
  // against Problem 1 at the moments the closed form read, bracketed by the exact moments'
  // certificate and a 50-digit witness; the upper bound likewise, through the mirrored problem.
  bool rounding_box = false;
};

// The §6 table for the given technique names (InputError for names without an LP counterpart).
std::vector<VerifyTarget> verify_targets(const std::vector<std::string>& techniques,
                                         const TechniqueParams& params);
// The technique parameters verify uses: the rows it judges Exact without their relaxations (each
// moment bias and TechniqueOption::zero_is_sharp option at 0), the others with their own.
TechniqueParams verify_params(TechniqueParams params);

// A depth distribution and a fragment depth: where an instance came from, for the report.
struct VerifyInstance {
  std::string source;
  std::vector<double> depths, weights;
  double zf = 0;
};

// Seeded random instances: 1..8 atoms on [0, 1] and mixtures of two smooth bumps.
std::vector<VerifyInstance> random_verify_instances(int count, uint64_t seed);
// `count` real kernels: receivers of `views` drawn uniformly with `seed`, each with its kernel's
// depths and weights and its test depth z_f - delta_f (dataset_instances.cpp).
std::vector<VerifyInstance> dataset_verify_instances(const std::vector<ViewData>& views,
                                                     const EvalSettings& settings, int count,
                                                     uint64_t seed);

// How far a closed form may sit above an LP witness before it counts as impossible: the closed
// forms at alpha = 0 lose digits on near-singular moments. Reports print this constant.
constexpr double kAboveLpSlack = 1e-6;
// The largest rounding allowance an instance gets (see solve_continuous in verification.cpp).
constexpr double kMaxRoundingAllowance = 1e-2;
// A continuous bracket wider than this leaves an instance unresolved (the exchange stalled).
constexpr double kUnresolvedBracket = 1e-6;

struct VerifyCase {
  size_t instance = 0;
  std::vector<double> moments;  // what the closed form read (after storage emulation)
  double closed_form = 0;
  std::vector<double> lp;  // per grid; NaN where the LP failed
  // max over grids of G_cf(moments of the LP's distribution) - (its mass below z_f): > 0 is
  // impossible for a correct infimum (see verification.cpp).
  double above_witness = -std::numeric_limits<double>::infinity();
  // The continuous LP (last column of `lp` when verify runs it): its bracket's width, whether its
  // certificate is a proof, and how far rounding the moments to double moves G to first order
  // (sum_j |dG/db_j| E|b_j| 2^-49, dG/db_j the certificate's coefficients): the closed form reads
  // rounded moments, so |dG| up to that is the moments' doing, not the closed form's.
  double bracket = 0;
  bool proven = true;
  double rounding = 0;
  // target.upper: the closed form's G + w_1 and the LP's maximum on the finest grid (NaN where
  // either gives no number); `upper_limited` when a canonical node lay beyond the LP's reach, so
  // that the LP's maximum may only be lower.
  double closed_upper = std::numeric_limits<double>::quiet_NaN();
  double lp_upper = std::numeric_limits<double>::quiet_NaN();
  bool upper_limited = false;
  // target.rounding_box: Problem 1 at the read moments lies in [box_lower, box_upper]; NaN where
  // the read moments have no witness (outside the moment cone: nothing to judge). The upper bound
  // G+ at the read moments lies in [upper_floor, lp_upper] (lp_upper then is the mirrored
  // certificate's bound, not a grid LP's maximum).
  double box_lower = std::numeric_limits<double>::quiet_NaN();
  double box_upper = std::numeric_limits<double>::quiet_NaN();
  double upper_floor = std::numeric_limits<double>::quiet_NaN();
  double upper_rounding = 0;  // as `rounding`, from the mirrored problem's certificate
  // The worst cases only: the finest grid's LP solved by the exact arbiter (lp/exact_backend.h)
  // with the distribution's exact image as right-hand side; NaN elsewhere, or where it failed.
  double lp_exact = std::numeric_limits<double>::quiet_NaN();
};

// One instance's judged comparison: the interval the verdict holds the closed form's G (or, for
// Hamburger's upper bound, G + w_1) to, the allowance beyond it, and how far outside it lies. The
// interval is the continuous LP's bracket [G - width, G] (the finest grid's G where there is no
// continuous column), Problem 1 at the read moments (rounding-box rows), or only an upper end
// (storage and lower-bound rows).
struct VerifyJudgement {
  VerifyCase c;
  bool upper = false;     // G + w_1 against G+ (VerifyTarget::upper), else G
  bool read_box = false;  // the bracket is Problem 1 at the read moments (verify/rounding_box.h)
  double closed_form = 0;
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  double allowed = 0;  // tolerance (or slack) plus the instance's allowance
  double outside() const { return std::max({0.0, lo - closed_form, closed_form - hi}); }
  // > 0: the instance fails the verdict.
  double beyond() const { return outside() - allowed; }
};

struct VerifyGridStats {
  int grid = 0;
  size_t compared = 0, lp_failures = 0;
  double max_difference = 0, mean_difference = 0;
};

struct VerifySolverResult {
  VerifyTarget target;
  size_t instances = 0, undefined = 0;  // undefined: the closed form returned no number
  std::vector<VerifyGridStats> grids;
  size_t beyond_tolerance = 0;  // |dG| > tolerance on the finest grid
  size_t above_lp = 0;          // above_witness > 1e-6: impossible for a correct infimum
  size_t above_finest = 0;      // closed form > LP on the finest grid + 1e-6
  // The continuous LP: its widest bracket and how many of its certificates are not proofs.
  double widest_bracket = 0;
  size_t unproven = 0;
  // Instances whose bracket is wider than 1e-6 (the exchange stalled on an LP it could not
  // certify): judged only from above there, against the bracket's lower end from below.
  size_t unresolved = 0;
  // target.rounding_box: instances whose read moments have no witness (judged against the exact
  // moments' LP instead) and the largest distance of a closed form outside its bracket.
  size_t unwitnessed = 0;
  double box_max_outside = 0;
  std::vector<VerifyCase> worst;        // by |dG| on the finest grid, largest first
  std::vector<VerifyCase> worst_above;  // above an LP witness, by how far (largest first)
  // Judged G and G + w_1: the failures (VerifyJudgement::beyond > 0) first, largest first, then
  // the others by their distance outside their bracket.
  std::vector<VerifyJudgement> worst_outside;
  // Storage rows judged against their box (target.storage_box with the continuous ground
  // truth): beyond_tolerance counts closed forms above the box's G by more than alpha + 1e-6.
  bool box_judged = false;
  // max G_cf - G_box (storage rows), max G_cf - G_LP (exceedance rows)
  double largest_excess = -std::numeric_limits<double>::infinity();
  // target.upper: instances compared, those whose nodes lay beyond the LP's reach (judged from
  // one side only), the largest |G+_cf - G+_LP| of the others, and how many miss the tolerance.
  size_t upper_compared = 0, upper_limited = 0, upper_beyond = 0;
  double upper_max_difference = 0;
  bool passed() const {
    if (target.lower_bound) return above_finest == 0 && above_lp == 0;
    return !judged() ||
           (beyond_tolerance == 0 && above_lp == 0 && (!target.upper_judged || upper_beyond == 0));
  }
  bool judged() const { return target.exact || target.lower_bound || box_judged; }
  // Whether a failure here fails verify (exit status 5).
  bool decides_exit() const { return judged() && (!box_judged || target.storage_strict); }
};

using TechniqueMaker = std::function<std::unique_ptr<Technique>()>;

// Compares `make()`'s technique with the LP on every instance and grid (grids ascending), then,
// when `continuous`, with Problem 1 on the continuous interval (continuous/continuous.h; power
// bases in local coordinates, continuous/local_power.h), which then decides. Deterministic for any
// thread count.
VerifySolverResult verify_solver(const VerifyTarget& target, const TechniqueMaker& make,
                                 std::span<const VerifyInstance> instances,
                                 const std::vector<int>& grids, bool continuous, double tolerance,
                                 int worst_count, int threads);

}  // namespace mb
