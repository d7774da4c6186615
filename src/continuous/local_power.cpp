#include "continuous/local_power.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mb::lp {

Basis power_basis(int degree) {
  std::vector<std::string> powers;
  for (int k = 1; k <= degree; ++k) powers.push_back(k == 1 ? "z" : "z^" + std::to_string(k));
  return Basis::parse(powers);
}

LocalPowerSolution solve_power_locally(const LocalPowerProblem& problem,
                                       std::span<const double> depths,
                                       std::span<const double> weights, double zf, Backend& backend,
                                       const ContinuousSettings& settings) {
  double total = 0, mean = 0, second = 0;
  for (size_t i = 0; i < depths.size(); ++i) total += weights[i], mean += weights[i] * depths[i];
  mean /= total;
  for (size_t i = 0; i < depths.size(); ++i)
    second += weights[i] * (depths[i] - mean) * (depths[i] - mean);
  // One atom has no spread: z_f's distance from it (or 1) sets the scale instead.
  double scale = std::sqrt(second / total);
  if (!(scale > 1e-12 * std::max(1.0, std::abs(mean))))
    scale = zf != mean ? std::abs(zf - mean) : 1.0;
  const auto to_u = [&](double z) { return (z - mean) / scale; };
  // The seed grid covers the distribution's scale (|u| <= kLocalSeedReach) within [lo, hi]; the
  // ends of [lo, hi] join as points, and the exchange adds what lies between where phi needs it. A
  // grid over all of a wide [lo, hi] would give the LP columns of size (hi / 4)^n for no gain.
  const double u_lo = to_u(problem.lo), u_hi = to_u(problem.hi);
  Discretization disc{std::max(u_lo, -kLocalSeedReach), std::min(u_hi, kLocalSeedReach),
                      problem.seed_grid, false};
  if (!(disc.lo < disc.hi)) disc.lo = u_lo, disc.hi = u_hi;  // [lo, hi] beyond the reach
  disc.window_lo = -4, disc.window_hi = 4;
  const ProblemFactory factory(power_basis(problem.degree), disc);
  std::vector<double> u(depths.size());
  std::transform(depths.begin(), depths.end(), u.begin(), to_u);
  Problem p = factory.from_distribution(u, weights, to_u(zf));
  std::vector<double> extra(problem.extra_points.size());
  std::transform(problem.extra_points.begin(), problem.extra_points.end(), extra.begin(), to_u);
  // The exchange works on |u| <= reach (the seed grid, the atoms and z_f); the certificate covers
  // the rest as tails, and where phi rises above the step there, the exchange adds points out to
  // where columns reach ~1e8 ((u / 4)^n, rows being orthonormal on [-4, 4]). The LP's optimality
  // tolerance scales with its largest column, so columns are kept as small as the answer allows.
  double reach = std::max(kLocalSeedReach, std::abs(to_u(zf)));
  for (double z : u) reach = std::max(reach, std::abs(z));
  const double inner_lo = std::max(u_lo, -reach), inner_hi = std::min(u_hi, reach);
  extra.push_back(inner_lo);
  extra.push_back(inner_hi);
  factory.add_points(p, extra);
  LocalPowerSolution out;
  out.mean = mean;
  out.scale = scale;
  ContinuousSolver solver(factory, settings);
  solver.set_interval(inner_lo, inner_hi);
  solver.set_tails(u_lo, u_hi, problem.degree % 2 == 0 ? problem.degree : 0,
                   4 * std::pow(10.0, 8.0 / problem.degree));
  out.solution = solver.solve(p, backend, u, weights);
  // phi(u) = sum_k c_k ((z - mean) / scale)^k, expanded in powers of z.
  const std::vector<long double>& c = out.solution.coefficients;
  out.coefficients.assign(c.size(), 0.0L);
  for (size_t k = 0; k < c.size(); ++k) {
    long double binomial = 1;  // binom(k, j) (-mean)^(k - j) / scale^k, for j = k down to 0
    const long double inverse = 1.0L / std::pow((long double)scale, (long double)k);
    for (size_t j = k + 1; j-- > 0;) {
      out.coefficients[j] +=
          c[k] * binomial * std::pow(-(long double)mean, (long double)(k - j)) * inverse;
      binomial = binomial * j / (k - j + 1);
    }
  }
  for (size_t j = 0; j < out.solution.finite.support.size(); ++j) {
    out.support.push_back(mean + scale * p.point(out.solution.finite.support[j]));
    out.weights.push_back(out.solution.finite.weights[j]);
  }
  return out;
}

}  // namespace mb::lp
