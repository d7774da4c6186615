#include "verify/verification.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "continuous/continuous.h"
#include "continuous/discretized.h"
#include "continuous/local_power.h"
#include "continuous/moment_box.h"
#include "lp/exact_backend.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "moments/hamburger.h"
#include "scene/procedural.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"
#include "verify/rounding_box.h"

namespace mb {

namespace {
struct Witness {
  std::vector<double> points, weights;
};
// The continuous LP for one instance into the case's last column and witness: power bases in
// local coordinates (on R for Hamburger and VSM), others by the exchange in depth coordinates.
void solve_continuous(const VerifyTarget& target, const Basis& basis, int degree,
                      const lp::ProblemFactory& seed, const VerifyInstance& inst,
                      lp::Backend& backend, VerifyCase& c, Witness& witness) {
  lp::ContinuousSolution s;
  std::vector<long double> coefficients;  // phi in the LP basis: c_0 + sum_j c_j b_j
  if (degree > 0) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const lp::LocalPowerProblem problem{degree, target.on_r ? -kInf : target.lo,
                                        target.on_r ? kInf : target.hi, lp::kContinuousSeedGrid};
    lp::LocalPowerSolution local =
        lp::solve_power_locally(problem, inst.depths, inst.weights, inst.zf, backend);
    if (target.rounding_box && local.solution.ok() && local.solution.proven) {
      const RoundedMomentBracket b =
          six_moment_bracket(c.moments, inst.zf, local.solution.coefficients, local.solution.delta,
                             local.solution.violation, local.mean, local.scale);
      if (b.inside) c.box_lower = b.lower, c.box_upper = b.upper, c.upper_floor = b.upper_at;
    }
    s = std::move(local.solution);
    witness.points = std::move(local.support);
    witness.weights = std::move(local.weights);
    coefficients = std::move(local.coefficients);
  } else {
    lp::Problem problem = seed.from_distribution(inst.depths, inst.weights, inst.zf);
    s = lp::ContinuousSolver(seed).solve(problem, backend, inst.depths, inst.weights);
    for (size_t j = 0; j < s.finite.support.size(); ++j) {
      witness.points.push_back(problem.point(s.finite.support[j]));
      witness.weights.push_back(s.finite.weights[j]);
    }
    coefficients = s.coefficients;
  }
  if (!s.ok()) {
    witness = {};
    return;
  }
  double total = 0;
  for (double& w : witness.weights) total += (w = std::max(0.0, w));
  for (double& w : witness.weights) w /= total;
  c.lp.back() = s.upper;
  c.bracket = s.width();
  c.proven = s.proven;
  // First-order effect of rounding each moment sum E[b_j] to double: a few ulps of E|b_j|.
  long double rounding = 0;
  for (size_t j = 0; j < basis.size() && j + 1 < coefficients.size(); ++j) {
    long double scale = 0;
    for (size_t a = 0; a < inst.depths.size(); ++a)
      scale += inst.weights[a] * std::abs((long double)basis[j](inst.depths[a]));
    rounding += std::abs(coefficients[j + 1]) * scale;
  }
  // Capped: the first-order estimate assumes every moment rounds the worst way, and with a narrow
  // kernel's dual coefficients (~1e12 in raw powers) it reaches ~1, where recomputing the bound in
  // 60 digits from the double-rounded moments moves it by at most 8.0e-3 (hamburger6, garden/east
  // texel (218,152); results/FINDINGS.md §7b); uncapped, a hamburger6 off by 0.57 passed.
  c.rounding = std::min(kMaxRoundingAllowance, double(rounding * std::ldexp(1.0L, -49)));
}

// The box problem of the technique's storage format for one instance (VerifyTarget::storage_box)
// into the case's last column and witness: the stored values the closed form read, the format's
// tolerance, on [0, 1]. A map stores depths in [0, 1] (docs/reference.md §4), so the property a
// storage variant must have is never to be darker than a distribution of depths there that could
// have produced its stored values, whatever interval its closed form solves on (Hamburger's R
// gives a lower G, and judging on it would ask more than the map's information implies).
void solve_storage_box(const Basis& basis, const MomentStorage& storage,
                       std::span<const double> tolerance, const VerifyInstance& inst, VerifyCase& c,
                       Witness& witness) {
  const lp::MomentBox box{stored_values(storage, c.moments),
                          std::vector<double>(tolerance.begin(), tolerance.end()),
                          storage.transform, storage.offset};
  const lp::ContinuousDomain domain = lp::ContinuousDomain::interval(0, 1);
  constexpr int kSeedGrid = lp::kContinuousSeedGrid;
  std::vector<double> seeds(inst.depths.begin(), inst.depths.end());
  for (int k = 0; k <= kSeedGrid; ++k)
    seeds.push_back(domain.lo + (domain.hi - domain.lo) * k / kSeedGrid);
  const lp::ContinuousBoxAnswer a =
      lp::solve_moment_box_continuous(basis, box, inst.zf, domain, seeds);
  if (!a.ok()) return;
  c.lp.back() = a.upper;
  c.bracket = a.width();
  c.proven = a.proven;
  c.rounding = 0;  // the box holds the moments' rounding
  double total = 0;
  for (double w : a.finite.weights) total += std::max(0.0, w);
  witness.points = a.finite.support;
  for (double w : a.finite.weights) witness.weights.push_back(std::max(0.0, w) / total);
}

}  // namespace

std::vector<VerifyTarget> verify_targets(const std::vector<std::string>& techniques,
                                         const TechniqueParams& params) {
  std::vector<VerifyTarget> out;
  for (const auto& name : techniques) {
    const TechniqueRow* row = find_technique(name);
    if (!row || !row->verify || row->prefix()) {
      std::string valid;
      for (const auto& r : technique_registry())
        if (r.verify) valid += (valid.empty() ? "" : ", ") + r.name;
      throw InputError("verify.techniques: '" + name +
                       "' has no LP ground truth in docs/reference.md §6; valid: " + valid);
    }
    // The registry row's recipe (techniques/registry.h) for these parameters.
    using Judge = VerifyRecipe::Judge;
    const VerifyRecipe& r = *row->verify;
    VerifyTarget t;
    t.technique = name;
    t.lp_basis = r.lp_basis(params);
    t.lo = r.lo;
    t.hi = r.hi;
    t.exact = r.judge == Judge::Exact;
    t.lower_bound = r.judge == Judge::LowerBound;
    t.exceedance = r.judge == Judge::Exceedance;
    t.storage_box = r.judge == Judge::StorageBox;
    t.on_r = r.on_r;
    t.cantelli_support = r.cantelli_support;
    t.alpha = r.alpha ? params.number(*r.alpha) : 0;
    t.hamburger_moments = r.hamburger_moments;
    t.upper = t.exact && t.on_r && t.hamburger_moments > 0;
    t.rounding_box = t.upper && t.hamburger_moments == 6;
    t.upper_judged = t.upper;
    out.push_back(std::move(t));
  }
  return out;
}

TechniqueParams verify_params(TechniqueParams p) {
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    if (row->verify && row->verify->judge == VerifyRecipe::Judge::Exact)
      for (const TechniqueOption* o : row->options)
        if (o->moment_bias || o->zero_is_sharp) p.set(*o, 0);
  return p;
}

std::vector<VerifyInstance> random_verify_instances(int count, uint64_t seed) {
  SeededRandom rng(seed);
  std::vector<VerifyInstance> out(count);
  for (int i = 0; i < count; ++i) {
    VerifyInstance& v = out[i];
    double total = 0;
    if (i % 10 < 8) {
      const int atoms = 1 + i % 8;
      for (int k = 0; k < atoms; ++k) {
        v.depths.push_back(rng.uniform(0.001, 0.999));
        v.weights.push_back(rng.uniform(0.05, 1));
      }
      v.source = "random:" + std::to_string(atoms) + " atoms";
    } else {  // a continuous mixture of two bumps, 32 atoms each
      for (int bump = 0; bump < 2; ++bump) {
        const double centre = rng.uniform(0.1, 0.9), width = rng.uniform(0.01, 0.1),
                     mass = rng.uniform(0.2, 1);
        for (int k = 0; k < 32; ++k) {
          v.depths.push_back(std::clamp(centre + width * (k - 15.5) / 16, 0.001, 0.999));
          v.weights.push_back(mass * std::exp(-0.5 * std::pow((k - 15.5) / 8, 2)));
        }
      }
      v.source = "random:mixture";
    }
    for (double w : v.weights) total += w;
    for (double& w : v.weights) w /= total;
    v.zf = rng.uniform(0.001, 0.999);
  }
  return out;
}

namespace {

// Cantelli's extremal two points keep mean and variance: z_f and mu - sigma^2 / (z_f - mu).
// Further out than ten interval widths the columns' size breaks the LP's scaling (and the weight
// there is tiny): the interval decides.
void add_cantelli_support(const VerifyTarget& target, const VerifyInstance& inst,
                          const lp::ProblemFactory& factory, lp::Problem& problem) {
  double mean = 0, second = 0;
  for (size_t a = 0; a < inst.depths.size(); ++a) {
    const double z = inst.depths[a], w = inst.weights[a];
    mean += w * z, second += w * z * z;
  }
  const double zf = inst.zf, variance = std::max(0.0, second - mean * mean);
  const double reach = 10 * (target.hi - target.lo);
  const double far = zf != mean ? mean - variance / (zf - mean) : zf;
  if (far >= target.lo - reach && far <= target.hi + reach) {
    const double points[2] = {zf, far};
    factory.add_points(problem, points);
  }
}

// G of the grid LP for one instance (NaN when no backend answers it), and its optimal
// distribution as the witness. The LP sees the exact distribution (its depths join I), so it is
// feasible and G_LP <= F_Z.
// The grid's LP of an instance: its distribution's depths among the points, and Cantelli's
// support where the target needs it.
lp::Problem grid_problem(const VerifyTarget& target, const VerifyInstance& inst,
                         const lp::ProblemFactory& factory) {
  lp::Problem problem = factory.from_distribution(inst.depths, inst.weights, inst.zf);
  if (target.cantelli_support) add_cantelli_support(target, inst, factory, problem);
  return problem;
}

double solve_grid(const VerifyTarget& target, const VerifyInstance& inst,
                  const lp::ProblemFactory& factory, lp::Backend& fast, lp::Backend& glpk,
                  Witness& witness) {
  lp::Problem problem = grid_problem(target, inst, factory);
  lp::Solution s = fast.solve(problem);
  if (s.status != lp::ProblemStatus::Optimal) s = glpk.solve(problem);
  if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal)
    return std::numeric_limits<double>::quiet_NaN();
  double total = 0;
  for (size_t j = 0; j < s.support.size(); ++j) {
    witness.points.push_back(problem.point(s.support[j]));
    witness.weights.push_back(std::max(0.0, s.weights[j]));
    total += witness.weights.back();
  }
  for (double& weight : witness.weights) weight /= total;
  return s.G;
}

// Hamburger's upper bound G + w_1 from the canonical distribution through z_f (moments/hamburger.h)
// against the LP's maximum (Problem::behind) with the canonical nodes among the LP's points: both
// are then the supremum over R of the mass at or in front of z_f (the LP's points lie in R, and
// the canonical distribution is among its distributions), so they must agree to the tolerance.
// Both in the kernel's local coordinates u = (z - mean) / spread, where both bounds are the same
// (Problem 1 on R with power moments is invariant under z -> (z - c) / s): raw moments of a
// narrow kernel rounded to double move either by up to 1e-4 (FINDINGS §7b), which is the
// moments' doing and not what this compares. The LP's grid spans the kernel's atoms +- 4 spreads.
void solve_upper(const VerifyTarget& target, const VerifyInstance& inst, VerifyCase& c,
                 lp::Backend& fast, lp::Backend& glpk) {
  const int m = target.hamburger_moments;
  double mean = 0, spread = 0;
  for (size_t a = 0; a < inst.depths.size(); ++a) mean += inst.weights[a] * inst.depths[a];
  for (double z : inst.depths) spread = std::max(spread, std::abs(z - mean));
  if (spread == 0) spread = 1;
  std::vector<double> u(inst.depths.size());
  for (size_t a = 0; a < u.size(); ++a) u[a] = (inst.depths[a] - mean) / spread;
  const double uf = (inst.zf - mean) / spread;
  double b[6] = {};
  for (size_t a = 0; a < u.size(); ++a) {
    double power = 1;
    for (int j = 0; j < m; ++j) b[j] += inst.weights[a] * (power *= u[a]);
  }
  const MsmBound<double> r = m == 4 ? hamburger4(b, uf) : hamburger6(b, uf);
  if (!std::isfinite(r.lower + r.at_zf)) return;
  c.closed_upper = r.lower + r.at_zf;
  const double lo = std::min(uf, -1.0) - 4, hi = std::max(uf, 1.0) + 4;
  const lp::ProblemFactory factory(Basis::parse(target.lp_basis),
                                   lp::Discretization{lo, hi, 513, false});
  lp::Problem problem = factory.from_distribution(u, inst.weights, uf);
  const double reach = 10 * (hi - lo);
  std::vector<double> nodes;
  for (int n = 0; n < r.node_count; ++n) {
    const bool near = r.nodes[n] >= lo - reach && r.nodes[n] <= hi + reach;
    if (near && r.weights[n] > 0) nodes.push_back(r.nodes[n]);
    c.upper_limited = c.upper_limited || (!near && r.weights[n] > 0);
  }
  factory.add_points(problem, nodes);
  problem.behind = true;
  lp::Solution s = fast.solve(problem);
  if (s.status != lp::ProblemStatus::Optimal) s = glpk.solve(problem);
  if (s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal) c.lp_upper = 1 - s.G;
}

// The upper-bound comparison of solve_upper, reduced: within the tolerance and the instance's
// rounding allowance, or (a node beyond reach) at least not below the LP's maximum.
void reduce_upper(const VerifyTarget& target, const std::vector<VerifyCase>& cases,
                  double tolerance, VerifySolverResult& result,
                  std::vector<VerifyJudgement>& judged) {
  for (const auto& c : cases) {
    if (!std::isfinite(c.closed_upper) || !std::isfinite(c.lp_upper)) continue;
    ++result.upper_compared;
    VerifyJudgement j{c, true};
    j.closed_form = c.closed_upper;
    j.allowed = tolerance + std::max(c.rounding, c.upper_rounding);
    if (std::isfinite(c.upper_floor)) {  // rounding-box rows: outside [upper_floor, lp_upper]
      j.read_box = true;
      j.lo = c.upper_floor, j.hi = c.lp_upper;
      result.upper_max_difference = std::max(result.upper_max_difference, j.outside());
    } else if (c.upper_limited) {  // the LP's maximum may only be lower
      ++result.upper_limited;
      j.lo = c.lp_upper;
    } else {
      j.lo = j.hi = c.lp_upper;
      result.upper_max_difference = std::max(result.upper_max_difference, j.outside());
    }
    result.upper_beyond += j.outside() > j.allowed;
    if (target.upper_judged) judged.push_back(std::move(j));
  }
}

// The judged comparisons into the result: the failures first, furthest beyond their allowance
// first, then the others by their distance outside the bracket.
void keep_worst_outside(std::vector<VerifyJudgement> judged, int worst_count,
                        VerifySolverResult& result) {
  const auto key = [](const VerifyJudgement& j) {
    return std::pair{j.beyond() > 0, j.beyond() > 0 ? j.beyond() : j.outside()};
  };
  std::stable_sort(judged.begin(), judged.end(),
                   [&](const auto& a, const auto& b) { return key(a) > key(b); });
  if (int(judged.size()) > worst_count) judged.resize(std::max(0, worst_count));
  result.worst_outside = std::move(judged);
}

// The closed form on an instance's stored moments: NaN when it gives no number.
double closed_form_answer(Technique& technique, std::span<const double> moments,
                          const VerifyInstance& inst) {
  FragmentInput in;
  in.moments = moments;
  in.zf = inst.zf;
  in.kernel_depths = inst.depths;
  in.kernel_weights = inst.weights;
  const size_t before = technique.failures();
  const double g = technique.shadow(in);
  return technique.failures() > before ? std::numeric_limits<double>::quiet_NaN() : g;
}

// The witness test. An LP solution is a distribution whose moments miss the instance's by the LP's
// tolerance; near the boundary of the moment space (Hankel determinants ~1e-17) that moves the
// optimum by far more than the tolerance, so G_LP itself is no bound on the closed form there. But
// the LP's distribution is an exact witness for its own moments: no correct infimum over I exceeds
// its mass below z_f (docs/reference.md §1). Returns the largest excess over `witnesses`.
template <class StoredMoments>
double above_witnesses(Technique& probe, const StoredMoments& stored_moments, double zf,
                       const std::vector<Witness>& witnesses, bool box_rows) {
  double above = -std::numeric_limits<double>::infinity();
  for (const Witness& w : witnesses) {
    if (w.points.empty()) continue;
    // A map stores depths in [0, 1] only (16-bit clamps its theta_4 coordinates there): a storage
    // row's witness must lie there to be a distribution the map could hold.
    if (box_rows &&
        std::any_of(w.points.begin(), w.points.end(), [](double z) { return z < 0 || z > 1; }))
      continue;
    const std::vector<double> moments = stored_moments(w.points, w.weights);
    double below = 0;
    for (size_t j = 0; j < w.points.size(); ++j)
      if (w.points[j] < zf) below += w.weights[j];
    VerifyInstance own;  // the witness as an instance: its own depths and weights
    own.depths = w.points;
    own.weights = w.weights;
    own.zf = zf;
    const double g = closed_form_answer(probe, moments, own);
    if (std::isfinite(g)) above = std::max(above, g - below);
  }
  return above;
}

// Whether the verdict judges the row's G (VerifySolverResult::judged; exceedance rows are
// reported only).
bool judged_result(const VerifyTarget& target, bool box_rows) {
  return target.exact || target.lower_bound || box_rows;
}

// The per-grid statistics, the judgement and the worst cases, reduced in case order.
void reduce_cases(const VerifyTarget& target, const std::vector<VerifyCase>& cases,
                  const std::vector<int>& grids, bool continuous, bool box_rows, double tolerance,
                  int worst_count, VerifySolverResult& result,
                  std::vector<VerifyJudgement>& judged) {
  result.grids.resize(cases[0].lp.size());
  for (size_t k = 0; k < grids.size(); ++k) result.grids[k].grid = grids[k];  // 0: continuous
  std::vector<std::pair<double, size_t>> finest, excess;
  for (const auto& c : cases) {
    if (!std::isfinite(c.closed_form)) {
      ++result.undefined;
      continue;
    }
    for (size_t k = 0; k < c.lp.size(); ++k) {
      VerifyGridStats& s = result.grids[k];
      if (!std::isfinite(c.lp[k])) {
        ++s.lp_failures;
        continue;
      }
      const double d = std::abs(c.closed_form - c.lp[k]);
      ++s.compared;
      s.max_difference = std::max(s.max_difference, d);
      s.mean_difference += d;
    }
    // Beyond the arithmetic slack, by the instance's rounding allowance: the witness's moments
    // are the instance's to within the LP's tolerance, and the closed form reads both rounded.
    // Storage rows: the biased moments are a mixture's, allowed alpha above (closed_form.h).
    const double allowance = box_rows ? target.alpha : c.rounding;
    const double above_by = c.above_witness - allowance;
    if (above_by > kAboveLpSlack) {
      ++result.above_lp;
      excess.push_back({above_by, c.instance});
    }
    if (!std::isfinite(c.lp.back())) continue;
    result.above_finest += c.closed_form > c.lp.back() + kAboveLpSlack;
    if (target.exceedance)
      result.largest_excess =
          std::max({result.largest_excess, c.closed_form - c.lp.back(), c.above_witness});
    const double d = std::abs(c.closed_form - c.lp.back());
    VerifyJudgement j{c};
    j.closed_form = c.closed_form;
    if (box_rows) {  // a lower bound of the box problem: judged from above only
      j.hi = c.lp.back();
      j.allowed = kAboveLpSlack + target.alpha;
    } else if (target.rounding_box && continuous && std::isfinite(c.box_lower)) {
      // Problem 1 at the read moments (verify/rounding_box.h), to the closed form's own rounding.
      j.read_box = true;
      j.lo = c.box_lower, j.hi = c.box_upper;
      j.allowed = tolerance + c.rounding;
      result.box_max_outside = std::max(result.box_max_outside, j.outside());
    } else {
      // The continuous LP's G lies in [upper - bracket, upper]: judged is the distance from
      // there. Read moments without a witness (singular: 1-3 atoms; or outside the moment cone)
      // are judged against the exact moments' LP, as the other rows.
      result.unwitnessed += target.rounding_box && continuous;
      j.lo = c.lp.back() - c.bracket, j.hi = c.lp.back();
      j.allowed = tolerance + c.rounding;
    }
    result.beyond_tolerance += j.outside() > j.allowed;
    // A valid lower bound is judged from above only, by the slack (VerifySolverResult::passed).
    if (target.lower_bound)
      j.lo = -std::numeric_limits<double>::infinity(), j.allowed = kAboveLpSlack;
    if (judged_result(target, box_rows)) judged.push_back(std::move(j));
    finest.push_back({box_rows ? c.closed_form - c.lp.back() : d, c.instance});
    if (box_rows) result.largest_excess = std::max(result.largest_excess, finest.back().first);
  }
  for (auto& s : result.grids)
    if (s.compared) s.mean_difference /= double(s.compared);
  if (continuous)
    for (const auto& c : cases) {
      if (!std::isfinite(c.lp.back())) continue;
      result.widest_bracket = std::max(result.widest_bracket, c.bracket);
      result.unproven += !c.proven;
      result.unresolved += c.bracket > kUnresolvedBracket;
    }
  const auto largest_first = [](const auto& a, const auto& b) { return a.first > b.first; };
  std::stable_sort(finest.begin(), finest.end(), largest_first);
  std::stable_sort(excess.begin(), excess.end(), largest_first);
  for (size_t k = 0; k < finest.size() && int(k) < worst_count; ++k)
    result.worst.push_back(cases[finest[k].second]);
  for (size_t k = 0; k < excess.size() && int(k) < worst_count; ++k)
    result.worst_above.push_back(cases[excess[k].second]);
}

// The worst cases through the exact arbiter (docs/lp-engine.md § The exact arbiter): the finest
// grid's LP as solve_grid poses it, solved in rational arithmetic, so that a large |dG| can be
// told apart from an LP answer that is off (results/FINDINGS.md §6b). Serial: the arbiter keeps
// global state, and there are only 2 x `verify.worst` cases per solver.
void arbitrate_worst(const VerifyTarget& target, std::span<const VerifyInstance> instances,
                     const lp::ProblemFactory& finest, VerifySolverResult& result) {
  auto exact = lp::make_exact_backend(lp::ExactRhs::DistributionImage);
  // A case often heads both lists: each instance is solved once.
  std::map<size_t, double> arbitrated;
  for (auto* list : {&result.worst, &result.worst_above})
    for (VerifyCase& c : *list) {
      auto [at, fresh] = arbitrated.try_emplace(c.instance, c.lp_exact);
      if (fresh) {
        const lp::Solution s = exact->solve(grid_problem(target, instances[c.instance], finest));
        if (s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal)
          at->second = s.G;
      }
      c.lp_exact = at->second;
    }
}

}  // namespace

VerifySolverResult verify_solver(const VerifyTarget& target, const TechniqueMaker& make,
                                 std::span<const VerifyInstance> instances,
                                 const std::vector<int>& grids, bool continuous, double tolerance,
                                 int worst_count, int threads) {
  VerifySolverResult result;
  result.target = target;
  result.instances = instances.size();
  const Basis lp_basis = Basis::parse(target.lp_basis);
  lp_basis.check_independent(target.lo, target.hi);
  // What the closed form reads: b(z) per depth, stored as its map would be (docs/reference.md §4),
  // filtered (the weighted sum), loaded. Serial: basis expressions are not thread-safe.
  const auto probe = make();
  const Basis& basis = probe->basis();
  const auto stored_moments = [&](std::span<const double> depths, std::span<const double> weights) {
    std::vector<double> moments = filtered_stored_values(probe->storage(), basis, depths, weights);
    load_moments(probe->storage(), moments);
    return moments;
  };
  std::vector<VerifyCase> cases(instances.size());
  for (size_t i = 0; i < instances.size(); ++i) {
    cases[i].instance = i;
    cases[i].moments = stored_moments(instances[i].depths, instances[i].weights);
    cases[i].lp.assign(grids.size() + (continuous ? 1 : 0),
                       std::numeric_limits<double>::quiet_NaN());
  }
  const int degree = lp::power_basis_degree(lp_basis);
  const bool box_rows = continuous && target.storage_box;
  result.box_judged = box_rows;
  const std::vector<double> box_tolerance =
      box_rows ? storage_tolerance(probe->storage(), basis) : std::vector<double>{};
  // The continuous LP's seed grid for bases other than powers (in depth coordinates).
  const lp::ProblemFactory seed_factory(
      lp_basis, lp::Discretization{target.lo, target.hi, lp::kContinuousSeedGrid, false});
  // The LP's optimal distribution per case and grid (its witness).
  std::vector<std::vector<Witness>> witnesses(instances.size(),
                                              std::vector<Witness>(cases[0].lp.size()));
  // One factory per grid, shared read-only (columns are computed up front).
  std::vector<std::unique_ptr<lp::ProblemFactory>> factories;
  for (int g : grids)
    factories.push_back(std::make_unique<lp::ProblemFactory>(
        lp_basis, lp::Discretization{target.lo, target.hi, g, false}));
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  {
    auto technique = make();
    auto glpk = lp::make_backend("glpk");
    // More functions than the fast backend takes (CSM's channels): GLPK first as well.
    auto fast = lp::make_backend(
        int(lp_basis.size()) <= lp::make_backend("fast")->max_functions() ? "fast" : "glpk");
#pragma omp for schedule(dynamic, 16)
    for (size_t i = 0; i < instances.size(); ++i)
      errors.capture([&] {
        cases[i].closed_form = closed_form_answer(*technique, cases[i].moments, instances[i]);
        for (size_t k = 0; k < grids.size(); ++k)
          cases[i].lp[k] =
              solve_grid(target, instances[i], *factories[k], *fast, *glpk, witnesses[i][k]);
        if (box_rows)
          solve_storage_box(technique->basis(), technique->storage(), box_tolerance, instances[i],
                            cases[i], witnesses[i].back());
        else if (continuous)
          solve_continuous(target, lp_basis, degree, seed_factory, instances[i], *fast, cases[i],
                           witnesses[i].back());
        // Six moments' upper bound needs the continuous LP's certificates (solve_upper_box).
        if (target.rounding_box) {
          if (continuous) solve_upper_box(instances[i], cases[i], *fast);
        } else if (target.upper) {
          solve_upper(target, instances[i], cases[i], *fast, *glpk);
        }
      });
  }
  errors.rethrow();
  // Serial: the technique's basis.
  for (size_t i = 0; i < instances.size(); ++i)
    if (std::isfinite(cases[i].closed_form))
      cases[i].above_witness =
          above_witnesses(*probe, stored_moments, instances[i].zf, witnesses[i], box_rows);
  std::vector<VerifyJudgement> judged;
  reduce_cases(target, cases, grids, continuous, box_rows, tolerance, worst_count, result, judged);
  if (!grids.empty()) arbitrate_worst(target, instances, *factories.back(), result);
  if (target.upper) reduce_upper(target, cases, tolerance, result, judged);
  keep_worst_outside(std::move(judged), worst_count, result);
  return result;
}

}  // namespace mb
