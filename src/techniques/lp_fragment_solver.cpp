#include "techniques/lp_fragment_solver.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <future>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "continuous/discretized.h"
#include "continuous/moment_box.h"
#include "moments/quantization_transform.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {

// The transform of a unorm box (docs/reference.md §8). `seed` is seed 000's theta_4 or theta_2 as
// hamburger4_16bit stores it (verbatim, so that unorm16 keeps the answers it gave before the
// transforms could be chosen); `canonical` and `optimized` come from quantization_transform.
// The optimized search runs once per basis and process: every thread's solver of every view
// reads the same answer, and a sweep's candidate pays for it inside its first view's time.
std::atomic<size_t> searches{0};

QuantizationTransform box_transform(const std::string& kind, const Basis& basis) {
  const std::vector<std::string> names = basis.names();
  if (kind == "seed") {
    MomentStorage seed;
    if (names == named_basis_set("power4"))
      seed = unorm16_power4_storage();
    else if (names == named_basis_set("power2"))
      seed = unorm16_power2_storage();
    else
      throw InputError(
          "lp.moment_transform: seed exists for the bases power4 (theta_4) and power2 (theta_2) "
          "only (seed 000 §4.3); expected canonical or optimized for the basis {" +
          joined(names, ", ") + "}");
    return {seed.transform, seed.offset};
  }
  if (kind != "optimized") return quantization_transform(basis, kind);
  // One slot per basis: the thread that claims it searches outside the lock, so a search holds
  // up only the solvers of its own basis (the same candidate), never another candidate's.
  static std::mutex mutex;
  static std::map<std::vector<std::string>, std::shared_future<QuantizationTransform>> found;
  std::promise<QuantizationTransform> promise;
  std::shared_future<QuantizationTransform> answer;
  bool mine = false;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = found.find(names);
    mine = it == found.end();
    answer = mine ? found.emplace(names, promise.get_future().share()).first->second : it->second;
  }
  if (mine) {
    ++searches;
    try {
      promise.set_value(quantization_transform(basis, kind));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return answer.get();
}

}  // namespace

size_t optimized_transform_searches() {
  return searches.load();
}

std::optional<LpMomentBox> lp_moment_box(const std::string& setting, const std::string& transform,
                                         const Basis& basis) {
  if (setting == "none") return std::nullopt;
  MomentStorage storage;
  if (setting == "double") {
    storage = double_storage();
  } else if (setting == "float32") {
    storage = float32_storage();
  } else if (setting.rfind("unorm", 0) == 0 && setting.size() > 5 &&
             setting.find_first_not_of("0123456789", 5) == std::string::npos &&
             setting.size() < 9) {
    QuantizationTransform t = box_transform(transform, basis);
    storage = unorm_storage(std::stoi(setting.substr(5)), std::move(t.A), std::move(t.c),
                            "lp.moment_box");
  } else {
    throw InputError(
        "lp.moment_box: expected one of none, double, float32, unorm8, unorm10, unorm16; got '" +
        setting + "'");
  }
  return LpMomentBox{storage, storage_tolerance(storage, basis)};
}

LpMomentBox lp_moment_box(const MomentStorage& storage, const Basis& basis) {
  return LpMomentBox{storage, storage_tolerance(storage, basis)};
}

namespace {

// lp.beta blends towards the LP's maximum G+ (docs/reference.md §2, "The maximum"): on the grid
// as Problem::behind, on the continuous interval as the exchange method's minimum of the reflected
// problem. The moment box answers the minimum alone, and a beta it would ignore must not pass as
// measured. read_lp_params refuses it in a config; this refuses it from every other caller
// (pss_lp sets its lp.beta from scatter.beta).
double checked_beta(const TechniqueParams& p, const std::optional<LpMomentBox>& box) {
  if (p.lp_beta > 0 && box)
    throw InputError("lp.beta: " + round_trip(p.lp_beta) +
                     " blends towards the LP's maximum, which the moment box does not solve; "
                     "expected lp.beta = 0 with a moment box (here: " +
                     box->storage.name() +
                     ", from lp.moment_box or an lp_stored: row), or lp.moment_box = none");
  return p.lp_beta;
}

// The continuous maximum's problem (docs/reference.md §2, "The maximum"): the least mass strictly
// behind z_f over distributions of z on [lo, hi] with moments E f_k(z) = b_k is the least mass
// strictly in front of -z_f over distributions of v = -z on [-hi, -lo] with E f_k(-v) = b_k, a
// minimum the exchange method certifies. The power basis is its own reflection up to signs
// (span{(-v)^k} = span{v^k}, as continuous/local_box.cpp's local_box_upper uses): it stays the
// power basis, so that the reflected problem keeps the local power path of its minimum
// (continuous/local_power.h), with the odd moments negated.
std::unique_ptr<lp::ProblemFactory> reflected_factory(const lp::ProblemFactory& factory,
                                                      double beta) {
  const Basis& basis = factory.basis();
  const lp::Discretization& d = factory.discretization();
  if (!(beta > 0) || !d.continuous) return nullptr;
  lp::Discretization r = d;
  r.lo = -d.hi, r.hi = -d.lo;
  if (d.window_lo < d.window_hi) r.window_lo = -d.window_hi, r.window_hi = -d.window_lo;
  return std::make_unique<lp::ProblemFactory>(
      lp::power_basis_degree(basis) > 0 ? basis : basis.reflected(), r);
}

}  // namespace

LpFragmentSolver::LpFragmentSolver(const Basis& basis, const lp::ProblemFactory& factory,
                                   const TechniqueParams& p)
    : LpFragmentSolver(basis, factory, p,
                       lp_moment_box(p.lp_moment_box, p.lp_moment_transform, basis)) {}

LpFragmentSolver::LpFragmentSolver(const Basis& basis, const lp::ProblemFactory& factory,
                                   const TechniqueParams& p, std::optional<LpMomentBox> box)
    : basis_(basis),
      factory_(factory),
      box_(std::move(box)),
      beta_(checked_beta(p, box_)),
      backend_(lp::make_backend(p.lp_backend)),
      upper_backend_(beta_ > 0 ? lp::make_backend(p.lp_backend) : nullptr),
      reflected_factory_(reflected_factory(factory, beta_)),
      reflected_power_(lp::power_basis_degree(factory.basis()) > 0) {}

const lp::Solution& LpFragmentSolver::solve(lp::Problem& problem, std::span<const double> depths,
                                            std::span<const double> weights, double zf,
                                            const lp::WarmStart* warm) {
  if (box_) {
    solve_box(filtered_stored_values(box_->storage, basis_, depths, weights), depths, zf);
    return s_;
  }
  if (factory_.discretization().continuous) {
    // The whole interval (docs/reference.md §2): the exchange extends a copy, from scratch, so
    // the caller's problem stays as given (eval moves its z_f between fragments of one texel).
    work_ = problem;
    s_ = lp::solve_discretized(factory_, work_, *backend_, depths, weights).finite;
    if (reflected_factory_) blend_with_reflected_minimum(problem, depths, weights);
    return s_;
  }
  backend_->solve_into(problem, warm, s_);
  if (upper_backend_) blend_with_maximum(problem);
  return s_;
}

const lp::Solution& LpFragmentSolver::solve_stored(std::span<const double> stored,
                                                   std::span<const double> depths, double zf) {
  if (!box_ || stored.size() != basis_.size())
    throw std::logic_error("LpFragmentSolver::solve_stored: no box, or " +
                           std::to_string(stored.size()) + " stored values for " +
                           std::to_string(basis_.size()) + " functions");
  solve_box({stored.begin(), stored.end()}, depths, zf);
  return s_;
}

void LpFragmentSolver::solve_box(std::vector<double> centre, std::span<const double> depths,
                                 double zf) {
  // Each fragment's box problem from scratch (GLPK; no warm start).
  s_.call = lp::CallStatus::Ok;
  const lp::Discretization& disc = factory_.discretization();
  const lp::MomentBox moment_box{std::move(centre), box_->tolerance, box_->storage.transform,
                                 box_->storage.offset};
  std::vector<double> points(depths.begin(), depths.end());
  const int grid = disc.continuous ? std::min(disc.grid, lp::kContinuousSeedGrid) : disc.grid;
  for (int k = 0; k < grid; ++k) points.push_back(disc.lo + (disc.hi - disc.lo) * k / (grid - 1));
  if (disc.continuous) {
    const lp::ContinuousBoxAnswer a = lp::solve_moment_box_continuous(
        basis_, moment_box, zf, lp::ContinuousDomain::interval(disc.lo, disc.hi), points);
    s_.G = std::clamp(a.upper, 0.0, 1.0);
    s_.status = a.finite.status;
    return;
  }
  points.push_back(zf);
  const lp::MomentBoxAnswer a = lp::solve_moment_box(basis_, moment_box, zf, points);
  s_.G = a.G;
  s_.status = a.status;
}

void LpFragmentSolver::blend_with_maximum(const lp::Problem& problem) {
  if (s_.call != lp::CallStatus::Ok || s_.status != lp::ProblemStatus::Optimal) return;
  upper_problem_ = problem;
  upper_problem_.behind = true;
  upper_backend_->solve_into(upper_problem_, nullptr, upper_);
  blend_with(upper_);
}

void LpFragmentSolver::blend_with_reflected_minimum(const lp::Problem& problem,
                                                    std::span<const double> depths,
                                                    std::span<const double> weights) {
  if (s_.call != lp::CallStatus::Ok || s_.status != lp::ProblemStatus::Optimal) return;
  const lp::ProblemFactory& reflected = *reflected_factory_;
  reflected_depths_.resize(depths.size());
  for (size_t t = 0; t < depths.size(); ++t) reflected_depths_[t] = -depths[t];
  if (!depths.empty()) {
    // The reflected kernel: the same moments E f_k(-v) (E v^k = (-1)^k b_k for the power basis).
    upper_problem_ = reflected.from_distribution(reflected_depths_, weights, -problem.zf);
  } else {
    reflected_moments_ = problem.moments;
    if (reflected_power_)
      for (size_t k = 0; k < reflected_moments_.size(); k += 2)
        reflected_moments_[k] = -reflected_moments_[k];
    upper_problem_ = reflected.from_moments(reflected_moments_, -problem.zf);
  }
  // The problem's own points beyond the kernel's (e.g. a closed form's nodes), reflected.
  reflected_points_.clear();
  for (double z : problem.extra.points) reflected_points_.push_back(-z);
  reflected.add_points(upper_problem_, reflected_points_);
  upper_ =
      lp::solve_discretized(reflected, upper_problem_, *upper_backend_, reflected_depths_, weights)
          .finite;
  blend_with(upper_);
}

void LpFragmentSolver::blend_with(const lp::Solution& behind) {
  if (behind.call != lp::CallStatus::Ok || behind.status != lp::ProblemStatus::Optimal) {
    s_.status =
        behind.status == lp::ProblemStatus::Optimal ? lp::ProblemStatus::Unstable : behind.status;
    return;
  }
  const double lower = std::clamp(s_.G, 0.0, 1.0);
  const double upper = std::clamp(1 - behind.G, lower, 1.0);
  s_.G = lower + beta_ * (upper - lower);
}

}  // namespace mb
