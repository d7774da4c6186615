#pragma once
// The one LP fragment solver (docs/design.md §Data flow): Problem 1 for one fragment's kernel
// distribution (docs/reference.md §2), on the grid (warm-started when the caller gives a start),
// on all of [lp.lo, lp.hi] by the exchange method (lp.discretization continuous), or over the box
// of moments a storage format's rounding leaves (lp.moment_box); with lp.beta the blend
// G + beta (G+ - G) towards the LP's maximum (on the grid or the continuous interval, not with
// a moment box). eval's views and the sweep's shadow target (eval/lp_view_solver.h), lp:<basis>
// of every family (techniques/lp_technique.h, hence oit and the sweep's transparency target) and
// msm_soft:lp:<basis> all answer through it.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "moments/storage.h"
#include "techniques/technique.h"

namespace mb {

// Whether a fragment needs an LP at all (docs/reference.md §2): G <= F_Z(z_f), so F_Z(z_f) = 0
// (`cdf_at_zf`, z_f already biased) gives G = 0 without solving, unless beta > 0 asks for the
// maximum G+, which may exceed 0 there.
inline bool needs_lp(double cdf_at_zf, double beta) {
  return cdf_at_zf > 0 || beta > 0;
}

// `lp.moment_box` (docs/reference.md §2, "Moments with a tolerance"): Problem 1 over every
// distribution whose moments, stored as `storage` holds them, lie within `tolerance` of the
// kernel's stored moments: the sharpest bound a shader reading such a map can claim.
struct LpMomentBox {
  MomentStorage storage;
  std::vector<double> tolerance;  // per stored value (moments/storage.h, storage_tolerance)
};
// lp.moment_box and lp.moment_transform (docs/reference.md §8): "none" -> no box; "double",
// "float32"; "unorm8", "unorm10", "unorm16" after the transform `transform` ("seed": seed 000's
// theta_4 or theta_2 verbatim, power4 and power2 only; "canonical"; "optimized": the basis's own,
// searched once per basis and process). InputError naming the key otherwise.
std::optional<LpMomentBox> lp_moment_box(const std::string& setting, const std::string& transform,
                                         const Basis& basis);
// How many optimized transforms this process has searched: one per basis, however many solvers
// and threads ask (the cost a sweep's candidate pays once).
size_t optimized_transform_searches();
// The box of a given format (a stored technique's own, lp_stored:<technique>).
LpMomentBox lp_moment_box(const MomentStorage& storage, const Basis& basis);

// Not thread-safe (its backends keep state): one per thread.
class LpFragmentSolver {
 public:
  // `basis` and `factory` outlive the solver; `params` gives lp.backend, lp.moment_box, lp.beta.
  // InputError for lp.beta > 0 with a moment box: the maximum it blends towards is solved on the
  // grid and on the continuous interval only.
  LpFragmentSolver(const Basis& basis, const lp::ProblemFactory& factory,
                   const TechniqueParams& params);
  // The same over `box` instead of the one lp.moment_box names (none: no box).
  LpFragmentSolver(const Basis& basis, const lp::ProblemFactory& factory,
                   const TechniqueParams& params, std::optional<LpMomentBox> box);
  // Whether solve reads `problem` (the moment box needs only the distribution).
  bool reads_problem() const { return !box_; }
  // The fragment's answer: `problem` is Problem 1 for the distribution (depths, weights) at z_f,
  // built by the factory; `warm` a warm start on the grid (null: from scratch, so the answer
  // does not depend on what was solved before). G is an answer where the call is Ok and the
  // status Optimal; a failed maximum (lp.beta) fails the fragment. `problem` is left as given.
  const lp::Solution& solve(lp::Problem& problem, std::span<const double> depths,
                            std::span<const double> weights, double zf,
                            const lp::WarmStart* warm = nullptr);
  // With a box: the box problem centred on `stored`, the values the map holds for this fragment
  // as a shader reads them, instead of the kernel's atoms stored one by one (FragmentInput::
  // stored_values); the kernel's depths join the grid.
  const lp::Solution& solve_stored(std::span<const double> stored, std::span<const double> depths,
                                   double zf);

 private:
  // G of the box problem around `centre` (stored values), on the grid and the kernel's depths or
  // (continuous) on all of [lo, hi] by the exchange method (continuous/moment_box.h).
  void solve_box(std::vector<double> centre, std::span<const double> depths, double zf);
  // lp.beta: s_.G <- G + beta (G+ - G), G+ = 1 - (the least mass behind z_f), solved cold (warm
  // bases remember the minimum's problems).
  void blend_with_maximum(const lp::Problem& problem);
  // The same on the continuous interval: the least mass behind z_f as the exchange method's
  // minimum of the reflected problem (v = -z on [-hi, -lo], below -z_f; see reflected_factory_).
  void blend_with_reflected_minimum(const lp::Problem& problem, std::span<const double> depths,
                                    std::span<const double> weights);
  // s_.G <- the blend with G+ = 1 - behind.G; a failed `behind` fails the fragment.
  void blend_with(const lp::Solution& behind);

  const Basis& basis_;
  const lp::ProblemFactory& factory_;
  std::optional<LpMomentBox> box_;
  double beta_ = 0;
  std::unique_ptr<lp::Backend> backend_, upper_backend_;
  // lp.beta > 0 on the continuous interval: Problem 1's factory for the reflected depths -z on
  // [-hi, -lo] (the reflected basis, or the power basis itself), with the same settings.
  std::unique_ptr<lp::ProblemFactory> reflected_factory_;
  bool reflected_power_ = false;  // the basis is z, .., z^n: its reflection stays the power basis
  lp::Problem work_, upper_problem_;
  lp::Solution s_, upper_;  // reused: no allocation per LP
  std::vector<double> reflected_depths_, reflected_moments_, reflected_points_;
};

}  // namespace mb
