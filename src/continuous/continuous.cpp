#include "continuous/continuous.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "basis/basis_derivatives.h"

namespace mb::lp {

namespace {

// Taylor models of phi use its derivatives 0..kOrder-1 at a cell's midpoint and bound the rest by
// the kOrder-th derivative over the cell: exact for polynomials up to degree kOrder - 1 (every
// power basis of the catalog), and for the other families the remainder shrinks like r^kOrder
// when a cell is bisected.
constexpr int kOrder = 8;
constexpr long double kEps = std::numeric_limits<long double>::epsilon();
// Rounding allowance per term: long double sums of at most 17 terms, each a product with a libm
// value accurate to a few ulps.
constexpr long double kRounding = 64 * kEps;
// Without closed-form derivatives, each seed cell is sampled at 2^kSampleDepth midpoints.
constexpr int kSampleDepth = 3;

long double factorial(int k) {
  long double f = 1;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}

// phi(z) = c_0 + sum_j c_j b_j(z), the finite LP's dual as a function on I.
class DualFunction {
 public:
  DualFunction(const Basis& basis, std::vector<long double> c) : basis_(basis), c_(std::move(c)) {
    analytic_ = true;
    for (size_t j = 0; j < basis.size(); ++j) analytic_ = analytic_ && basis[j].has_derivatives();
  }
  bool analytic() const { return analytic_; }

  // phi(z), and in `magnitude` the sum of its terms' magnitudes (for the rounding allowance).
  long double value(long double z, long double* magnitude = nullptr) const {
    long double v = c_[0], m = std::abs(c_[0]);
    for (size_t j = 0; j < basis_.size(); ++j) {
      long double b;
      if (analytic_)
        basis_[j].derivatives(z, 0, &b);
      else
        b = basis_[j](double(z));
      v += c_[j + 1] * b;
      m += std::abs(c_[j + 1] * b);
    }
    if (magnitude) *magnitude = m;
    return v;
  }

  // d[k] = phi^(k)(z) / k!, and magnitude[k] the same sum of |terms|, for k < kOrder.
  void taylor(long double z, long double* d, long double* magnitude) const {
    std::fill(d, d + kOrder, 0.0L);
    std::fill(magnitude, magnitude + kOrder, 0.0L);
    d[0] = c_[0], magnitude[0] = std::abs(c_[0]);
    long double derivatives[kOrder];
    for (size_t j = 0; j < basis_.size(); ++j) {
      basis_[j].derivatives(z, kOrder - 1, derivatives);
      for (int k = 0; k < kOrder; ++k) {
        d[k] += c_[j + 1] * derivatives[k];
        magnitude[k] += std::abs(c_[j + 1] * derivatives[k]);
      }
    }
    for (int k = 2; k < kOrder; ++k) d[k] /= factorial(k), magnitude[k] /= factorial(k);
  }

  // A bound of |phi^(kOrder)| / kOrder! over [a, b], term by term.
  long double remainder(long double a, long double b) const {
    long double s = 0;
    for (size_t j = 0; j < basis_.size(); ++j)
      if (c_[j + 1] != 0) s += std::abs(c_[j + 1]) * basis_[j].derivative_bound(kOrder, a, b);
    return s / factorial(kOrder);
  }

 private:
  const Basis& basis_;
  std::vector<long double> c_;
  bool analytic_ = true;
};

// An upper bound of phi over [a, b] from its Taylor model at the midpoint: the quadratic part's
// exact maximum on [-r, r], the higher terms by magnitude, the remainder, and rounding.
struct CellBound {
  long double upper, argmax;
  long double rounding;  // phi's own rounding allowance at the midpoint: no bisection removes it
};

CellBound bound_cell(const DualFunction& phi, long double a, long double b) {
  const long double m = (a + b) / 2, r = (b - a) / 2;
  long double d[kOrder], magnitude[kOrder];
  phi.taylor(m, d, magnitude);
  const auto quadratic = [&](long double t) { return d[0] + t * (d[1] + t * d[2]); };
  long double best_t = quadratic(-r) > quadratic(r) ? -r : r;
  if (d[2] < 0) {
    const long double vertex = -d[1] / (2 * d[2]);
    if (std::abs(vertex) <= r && quadratic(vertex) > quadratic(best_t)) best_t = vertex;
  }
  long double tail = 0, rounding = 0, rk = 1;
  for (int k = 0; k < kOrder; ++k, rk *= r) {
    if (k >= 3) tail += std::abs(d[k]) * rk;
    rounding += magnitude[k] * rk;
  }
  tail += phi.remainder(a, b) * rk;  // rk = r^kOrder here
  return {quadratic(best_t) + tail + kRounding * rounding, m + best_t, kRounding * magnitude[0]};
}

// The highest phi on [a, b] found by golden-section search (phi is unimodal on a cell small enough
// to matter), compared with the ends and `guess`.
long double highest_point(const DualFunction& phi, long double a, long double b,
                          long double guess) {
  constexpr long double kRatio = 0.6180339887498948482L;
  long double x = a, best = phi.value(a);
  for (long double z : {b, guess}) {
    const long double v = phi.value(z);
    if (v > best) best = v, x = z;
  }
  long double lo = a, hi = b;
  long double p = hi - kRatio * (hi - lo), q = lo + kRatio * (hi - lo);
  long double fp = phi.value(p), fq = phi.value(q);
  for (int i = 0; i < 60 && hi - lo > 1e-15L * std::max(1.0L, std::abs(lo)); ++i) {
    if (fp < fq) {
      lo = p, p = q, fp = fq, q = lo + kRatio * (hi - lo), fq = phi.value(q);
    } else {
      hi = q, q = p, fq = fp, p = hi - kRatio * (hi - lo), fp = phi.value(p);
    }
  }
  if (fp > best) best = fp, x = p;
  if (fq > best) best = fq, x = q;
  return x;
}

struct Violator {
  long double z, excess;
};

struct Scan {
  long double violation = 0;  // bound of max (phi - step) over I
  bool proven = true;
  long cells = 0;
  std::vector<Violator> violators;
};

// Bounds phi - step over [lo, hi] cell by cell (cells start between consecutive breakpoints and
// are bisected where the bound is not yet within the tolerance), and collects the points where phi
// truly exceeds the step. The breakpoints include z_f, so every cell lies on one side of the step.
Scan scan(const DualFunction& phi, const std::vector<long double>& breakpoints, long double zf,
          const ContinuousSettings& settings) {
  Scan out;
  struct Cell {
    long double a, b;
    int depth;
  };
  std::vector<Cell> stack;
  for (size_t i = breakpoints.size() - 1; i > 0; --i)
    stack.push_back({breakpoints[i - 1], breakpoints[i], 0});
  while (!stack.empty()) {
    const Cell cell = stack.back();
    stack.pop_back();
    ++out.cells;
    const long double step = cell.b <= zf ? 1 : 0;
    const long double mid = (cell.a + cell.b) / 2;
    const bool can_split = cell.b - cell.a > 4 * kEps * std::max(1.0L, std::abs(mid)) &&
                           out.cells + long(stack.size()) < settings.max_cells;
    if (phi.analytic()) {
      const CellBound bound = bound_cell(phi, cell.a, cell.b);
      const long double gap = bound.upper - step;
      if (gap <= settings.cell_tolerance) {
        out.violation = std::max(out.violation, gap);
        continue;
      }
      const long double z = highest_point(phi, cell.a, cell.b, bound.argmax);
      const long double excess = phi.value(z) - step;
      if (excess > settings.add_tolerance) {
        out.violators.push_back({z, excess});
        out.violation = std::max(out.violation, gap);
      } else if (cell.depth < settings.max_depth && can_split &&
                 gap - bound.rounding > settings.cell_tolerance) {
        stack.push_back({mid, cell.b, cell.depth + 1});
        stack.push_back({cell.a, mid, cell.depth + 1});
      } else {
        out.violation = std::max(out.violation, gap);
      }
    } else {
      // Sampling only: nothing is proven between the samples.
      out.proven = false;
      const long double excess = phi.value(mid) - step;
      if (excess > settings.add_tolerance) {
        const long double z = highest_point(phi, cell.a, cell.b, mid);
        out.violators.push_back({z, phi.value(z) - step});
        out.violation = std::max(out.violation, out.violators.back().excess);
      } else if (cell.depth < kSampleDepth && can_split) {
        stack.push_back({mid, cell.b, cell.depth + 1});
        stack.push_back({cell.a, mid, cell.depth + 1});
      } else {
        out.violation = std::max(out.violation, excess);
      }
    }
  }
  out.violation = std::max(out.violation, 0.0L);
  return out;
}

// The tail from `end` outwards (dir -1: below, +1: above) to `far`: phi(end + dir t) =
// sum_k d_k (dir t)^k + remainder. Over a finite tail the terms with a positive coefficient
// bound it. An infinite tail (Hamburger's I = R) needs every coefficient k >= 1 negative and no
// remainder, which rounding leaves in doubt when a coefficient is ~0 (a dual that is constant
// far out): there phi - delta (1 + z^n) is used instead, with delta just large enough, for an even
// degree n (1 + z^n >= 0, so this lowers phi everywhere and E[phi] by delta (1 + E[z^n])).
// Returns the bound of phi - delta (1 + z^n) - step on the tail, and raises `delta` as needed.
long double tail_bound(const DualFunction& phi, long double end, int dir, long double far,
                       long double step, int even_degree, long double& delta) {
  long double d[kOrder], magnitude[kOrder];
  phi.taylor(end, d, magnitude);
  const long double length = std::abs(far - end);
  const long double remainder = phi.remainder(std::min(end, far), std::max(end, far));
  long double e[kOrder], slack[kOrder], rounding = 0;
  for (int k = 0; k < kOrder; ++k) {
    e[k] = (dir < 0 && k % 2) ? -d[k] : d[k];
    slack[k] = kRounding * magnitude[k];
    rounding += slack[k];
  }
  if (std::isfinite(length)) {
    long double bound = d[0] + rounding, tk = length;
    for (int k = 1; k < kOrder; ++k, tk *= length) bound += std::max(0.0L, e[k] + slack[k]) * tk;
    return bound + remainder * tk - step;  // tk = length^kOrder
  }
  if (remainder > 0 || even_degree <= 0 || end * dir < 0)
    return std::numeric_limits<long double>::infinity();
  // (|end| + t)^n's Taylor coefficients in t: binom(n, k) |end|^(n - k), all >= 0.
  const long double a = std::abs(end);
  long double binomial = 1;
  for (int k = 1; k < kOrder; ++k) {
    binomial = binomial * (even_degree - k + 1) / k;
    const long double q = k <= even_degree ? binomial * std::pow(a, even_degree - k) : 0;
    const long double need = e[k] + slack[k];
    if (need <= 0) continue;
    if (q <= 0) return std::numeric_limits<long double>::infinity();
    delta = std::max(delta, 2 * need / q);
  }
  return d[0] + rounding - step;
}

// E_S[phi] over the distributions S with the problem's moments (from the atoms when known, which
// keeps the digits a narrow kernel's moments lose), and E_S of the terms' magnitudes, which sizes
// the rounding allowance.
struct DualMean {
  long double value = 0, magnitude = 0;
};

DualMean dual_mean(const DualFunction& phi, const std::vector<long double>& c,
                   const Problem& problem, std::span<const double> depths,
                   std::span<const double> weights) {
  DualMean mean;
  if (!depths.empty()) {
    long double total = 0;
    for (size_t i = 0; i < depths.size(); ++i) {
      long double m;
      mean.value += weights[i] * phi.value(depths[i], &m);
      mean.magnitude += weights[i] * m;
      total += weights[i];
    }
    mean.value /= total, mean.magnitude /= total;
    return mean;
  }
  mean.value = c[0], mean.magnitude = std::abs(c[0]);
  for (size_t j = 0; j < problem.moments.size(); ++j) {
    mean.value += c[j + 1] * problem.moments[j];
    mean.magnitude += std::abs(c[j + 1] * problem.moments[j]);
  }
  return mean;
}

// E[z^n], n the even degree whose tail term the certificate's delta multiplies.
long double power_mean(const Problem& problem, std::span<const double> depths,
                       std::span<const double> weights, int degree) {
  if (depths.empty()) return problem.moments[degree - 1];
  long double mean = 0, total = 0;
  for (size_t i = 0; i < depths.size(); ++i)
    mean += weights[i] * std::pow((long double)depths[i], degree), total += weights[i];
  return mean / total;
}

}  // namespace

long double DualCertificate::rounding() {
  return kRounding;
}

DualCertificate certify_dual(const Basis& basis, const std::vector<long double>& coefficients,
                             double zf_in, std::span<const double> points,
                             const ContinuousDomain& domain, const ContinuousSettings& settings) {
  const DualFunction phi(basis, coefficients);
  const long double lo = domain.lo, hi = domain.hi, zf = zf_in;
  // The cells cover [scan_lo, scan_hi]: [lo, hi] and the tails out to the probe limit. They
  // start between the given points there, the ends and z_f.
  const long double scan_lo =
      std::min(lo, std::max<long double>(domain.tail_lo, -domain.probe_limit));
  const long double scan_hi =
      std::max(hi, std::min<long double>(domain.tail_hi, domain.probe_limit));
  std::vector<long double> breakpoints{scan_lo, scan_hi};
  if (zf > scan_lo && zf < scan_hi) breakpoints.push_back(zf);
  long double beyond = 0;  // phi - step at points of I outside the cells (verify adds some)
  for (const double point : points) {
    const long double z = point;
    if (z > scan_lo && z < scan_hi) {
      breakpoints.push_back(z);
    } else if (z < scan_lo || z > scan_hi) {
      long double magnitude;
      const long double v = phi.value(z, &magnitude) - (z < zf ? 1 : 0);
      beyond = std::max(beyond, v + kRounding * magnitude);
    }
  }
  std::sort(breakpoints.begin(), breakpoints.end());
  breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());
  Scan found = scan(phi, breakpoints, zf, settings);
  DualCertificate out;
  // The tails of I beyond the cells, if any: bounded, never sampled (their columns would be
  // too large for the LP).
  for (const auto& [end, dir, far] : {std::tuple{scan_lo, -1, (long double)domain.tail_lo},
                                      std::tuple{scan_hi, 1, (long double)domain.tail_hi}}) {
    if (far == end) continue;
    // The step's least value on the tail (sufficient for phi <= step there).
    const long double step = (dir < 0 ? end < zf : far < zf) ? 1 : 0;
    beyond = std::max(beyond, tail_bound(phi, end, dir, far, step, domain.even_degree, out.delta));
  }
  out.cells = found.cells;
  out.proven = found.proven;
  out.violation = std::max(found.violation, beyond);
  // The largest violations first.
  std::sort(found.violators.begin(), found.violators.end(),
            [](const Violator& x, const Violator& y) { return x.excess > y.excess; });
  for (const Violator& v : found.violators) out.violators.push_back(double(v.z));
  return out;
}

ContinuousSolution ContinuousSolver::solve(Problem& problem, Backend& backend,
                                           std::span<const double> depths,
                                           std::span<const double> weights) const {
  const int per_round =
      settings_.points_per_round > 0 ? settings_.points_per_round : 2 * problem.rows;
  ContinuousSolution out;
  out.finite = backend.solve(problem);
  std::vector<double> points;
  for (;;) {
    if (!out.ok()) return out;
    ++out.rounds;
    out.coefficients = factory_.raw_coefficients(out.finite.duals);
    const DualFunction phi(factory_.basis(), out.coefficients);
    points.resize(problem.cols());
    for (int j = 0; j < problem.cols(); ++j) points[j] = problem.point(j);
    const DualCertificate found =
        certify_dual(factory_.basis(), out.coefficients, problem.zf, points, domain_, settings_);
    const long double delta = found.delta;
    out.delta = delta;
    out.cells = found.cells;
    out.proven = found.proven;
    out.violation = double(found.violation);
    // Weak duality: for every distribution S on I with these moments,
    // P_S(z < z_f) >= E_S[phi] - violation.
    const DualMean mean = dual_mean(phi, out.coefficients, problem, depths, weights);
    long double dual = mean.value;
    const long double magnitude = mean.magnitude;
    if (delta > 0) dual -= delta * (1 + power_mean(problem, depths, weights, domain_.even_degree));
    out.lower = double(dual - out.violation - kRounding * magnitude);
    out.upper = out.finite.G;
    if (found.violators.empty() || out.width() <= settings_.target_width ||
        out.rounds >= settings_.max_rounds)
      return out;
    // The largest violations first, one point each.
    points.assign(found.violators.begin(),
                  found.violators.begin() + std::min<size_t>(per_round, found.violators.size()));
    const Problem saved = problem;
    const int before = problem.extra.size();
    factory_.add_points(problem, points);
    if (problem.extra.size() == before) return out;  // nothing new: the finite LP decides
    Solution next = backend.solve(problem);
    // Several new points close together can leave the finite LP too ill-conditioned to certify:
    // then the worst violator alone. If that fails too, the exchange ends with the last certified
    // round, whose bracket is still valid (points added since only extend I).
    const auto failed = [](const Solution& s) {
      return s.call != CallStatus::Ok || s.status != ProblemStatus::Optimal;
    };
    if (failed(next) && points.size() > 1) {
      problem = saved;
      factory_.add_points(problem, std::span<const double>(points.data(), 1));
      next = backend.solve(problem);
    }
    if (failed(next)) {
      problem = saved;
      out.stalled = true;
      return out;
    }
    out.points_added += problem.extra.size() - before;
    out.finite = std::move(next);
  }
}

}  // namespace mb::lp
