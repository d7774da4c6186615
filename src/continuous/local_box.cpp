#include "continuous/local_box.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "continuous/local_power.h"
#include "lp/solution.h"

namespace mb::lp {

namespace {

// x rounded to double, then two ulps further in the direction `dir`: I's ends in u, outward.
double round_outward(long double x, int dir) {
  double d = double(x);
  for (int i = 0; i < 2; ++i) d = std::nextafter(d, dir * HUGE_VAL);
  return d;
}

// The least radius of a row of the local box, relative to its centre (at least 1).
constexpr double kLpResolution = 1e-10;

}  // namespace

LocalFrame local_frame(std::span<const double> moments, std::span<const double> tolerance,
                       double zf) {
  LocalFrame f;
  f.mean = moments[0];
  if (moments.size() < 2) {
    f.inverse = zf != moments[0] ? 1 / std::abs((long double)zf - f.mean) : 1;
    return f;
  }
  const long double variance = (long double)moments[1] - f.mean * f.mean;
  // What the tolerances leave undetermined of the variance: the box may hold a single atom.
  const long double floor =
      tolerance[1] + 2 * std::abs(f.mean) * tolerance[0] + (long double)tolerance[0] * tolerance[0];
  long double deviation = std::sqrt(std::max(variance, floor));
  if (!(deviation > 0)) deviation = zf != moments[0] ? std::abs(zf - f.mean) : 1;
  f.inverse = 1 / deviation;
  return f;
}

MomentBox local_moment_box(const LocalFrame& frame, std::span<const double> moments,
                           std::span<const double> tolerance) {
  const size_t n = moments.size();
  MomentBox box;
  for (size_t k = 1; k <= n; ++k) {
    // E[(z - mean)^k] = sum_j binom(k, j) (-mean)^(k - j) E[z^j], E[z^0] = 1 exactly.
    long double sum = 0, radius = 0, magnitude = 0, binomial = 1;
    for (size_t j = 0; j <= k; ++j) {
      const long double power = std::pow(-frame.mean, (long double)(k - j));
      const long double m = j == 0 ? 1.0L : moments[j - 1];
      const long double e = j == 0 ? 0.0L : tolerance[j - 1];
      sum += binomial * power * m;
      magnitude += std::abs(binomial * power * m);
      radius += binomial * std::abs(power) * e;
      binomial = binomial * (k - j) / (j + 1);
    }
    const long double scale = std::pow(frame.inverse, (long double)k);
    const long double centre = sum * scale;
    // The expansion's rounding: each of its 3k + 2 operations within LDBL_EPSILON of the terms'
    // magnitude; then the centre's rounding to double.
    long double r = (radius + (3 * k + 4) * LDBL_EPSILON * magnitude) * scale;
    r += std::abs(centre - (long double)double(centre));
    box.center.push_back(double(centre));
    box.tolerance.push_back(std::nextafter(double(r * (1 + 8 * LDBL_EPSILON)), HUGE_VAL));
  }
  return box;
}

LocalBoxAnswer solve_power_box_locally(double lo, double hi, std::span<const double> moments,
                                       std::span<const double> tolerance, double zf,
                                       const ContinuousSettings& settings) {
  const int degree = int(moments.size());
  LocalBoxAnswer out;
  out.frame = local_frame(moments, tolerance, zf);
  const LocalFrame& f = out.frame;
  MomentBox box = local_moment_box(f, moments, tolerance);
  // GLPK reads a row's bounds to 1e-12 of its scale (moment_box.cpp): a radius below that would
  // leave feasibility to the tolerance's call, and phase 1 and the box LP could read it
  // differently. A wider box is still a lower bound for every distribution in the narrower one.
  for (size_t k = 0; k < box.center.size(); ++k)
    box.tolerance[k] =
        std::max(box.tolerance[k], kLpResolution * std::max(1.0, std::abs(box.center[k])));
  const Basis basis = power_basis(degree);
  // As in continuous/local_power.h: the exchange works within the distribution's reach (a few
  // deviations, and z_f), the certificate covers the rest of I as tails, points may be added out
  // to where the columns reach ~1e8.
  const double u_lo = round_outward((lo - f.mean) * f.inverse, -1);
  const double u_hi = round_outward((hi - f.mean) * f.inverse, 1);
  const double zf_u = f.to_u(zf);
  const double reach = std::max(kLocalSeedReach, std::abs(zf_u));
  ContinuousDomain domain{std::max(u_lo, -reach), std::min(u_hi, reach), u_lo, u_hi};
  domain.even_degree = degree % 2 == 0 ? degree : 0;
  domain.probe_limit = 4 * std::pow(10.0, 8.0 / degree);
  if (!(domain.lo < domain.hi)) domain.lo = u_lo, domain.hi = u_hi;  // I lies beyond the reach
  const double seed_lo = std::max(domain.lo, -kLocalSeedReach),
               seed_hi = std::min(domain.hi, kLocalSeedReach);
  std::vector<double> seeds;
  for (int i = 0; i <= kContinuousSeedGrid; ++i)
    seeds.push_back(seed_lo + (seed_hi - seed_lo) * i / kContinuousSeedGrid);
  out.local = box;
  out.domain = domain;
  out.zf_u = zf_u;
  out.phase1 = find_box_points(basis, box, domain, seeds, settings);
  if (!out.phase1.found) return out;
  // Phase 1's support alone: a start GLPK finds feasible (with the seed grid beside it, its primal
  // simplex can call a box of 1e-10 infeasible among near-parallel columns); the exchange adds
  // what the optimum needs.
  out.box = solve_moment_box_continuous(basis, box, zf_u, domain, out.phase1.points, settings);
  for (size_t j = 0; j < out.box.finite.support.size(); ++j) {
    out.support.push_back(f.to_z(out.box.finite.support[j]));
    out.weights.push_back(out.box.finite.weights[j]);
  }
  return out;
}

LocalBoxUpper local_box_upper(const LocalBoxAnswer& answer, const ContinuousSettings& settings) {
  LocalBoxUpper out;
  if (!answer.ok()) return out;
  // v = -u: E[v^k] = (-1)^k E[u^k], the radii unchanged; I and its tails reflected.
  MomentBox box = answer.local;
  for (size_t k = 0; k < box.center.size(); k += 2) box.center[k] = -box.center[k];
  const ContinuousDomain& d = answer.domain;
  ContinuousDomain reflected{-d.hi, -d.lo, -d.tail_hi, -d.tail_lo};
  reflected.even_degree = d.even_degree;
  reflected.probe_limit = d.probe_limit;
  // Seeds that carry a distribution in the box: phase 1's points, else the least G's support. GLPK
  // can call a box of 1e-10 infeasible from one start and not from another (as in
  // solve_power_box_locally); a box widened tenfold still bounds G over this one from above.
  const Basis basis = power_basis(int(box.center.size()));
  std::vector<double> phase1, support;
  for (double u : answer.phase1.points) phase1.push_back(-u);
  for (double u : answer.box.finite.support) support.push_back(-u);
  for (int attempt = 0; attempt < 4 && !out.behind.ok(); ++attempt) {
    if (attempt == 2)
      for (double& t : box.tolerance)
        t *= 10;  // a superset: its largest mass is still an upper end
    out.behind = solve_moment_box_continuous(basis, box, -answer.zf_u, reflected,
                                             attempt % 2 ? support : phase1, settings);
  }
  if (!out.behind.ok()) return out;
  out.upper = std::clamp(1 - out.behind.lower, 0.0, 1.0);
  out.proven = out.behind.proven;
  return out;
}

}  // namespace mb::lp
