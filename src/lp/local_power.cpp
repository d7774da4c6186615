#include "lp/local_power.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mb::lp {

LocalPowerSolution solve_power_locally(const LocalPowerProblem& problem,
                                       std::span<const double> depths,
                                       std::span<const double> weights, double zf,
                                       Backend& backend, const ContinuousSettings& settings) {
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
  std::vector<std::string> powers;
  for (int k = 1; k <= problem.degree; ++k) powers.push_back(k == 1 ? "z" : "z^" + std::to_string(k));
  // The seed grid covers the distribution's scale (|u| <= kSeedReach) within [lo, hi]; the ends of
  // [lo, hi] join as points, and the exchange adds what lies between where phi needs it. A grid
  // over all of a wide [lo, hi] would give the LP columns of size (hi / 4)^n for no gain.
  constexpr double kSeedReach = 8, kReach = 64;
  const double u_lo = to_u(problem.lo), u_hi = to_u(problem.hi);
  Discretization disc{std::max(u_lo, -kSeedReach), std::min(u_hi, kSeedReach), problem.seed_grid,
                      false};
  if (!(disc.lo < disc.hi)) disc.lo = u_lo, disc.hi = u_hi;  // [lo, hi] beyond the reach
  disc.window_lo = -4, disc.window_hi = 4;
  const ProblemFactory factory(Basis::parse(powers), disc);
  std::vector<double> u(depths.size());
  std::transform(depths.begin(), depths.end(), u.begin(), to_u);
  Problem p = factory.from_distribution(u, weights, to_u(zf));
  std::vector<double> extra(problem.extra_points.size());
  std::transform(problem.extra_points.begin(), problem.extra_points.end(), extra.begin(), to_u);
  // Beyond |u| = kReach (or z_f's distance, if further) columns grow past (kReach / 4)^n: the
  // exchange works inside, and the certificate covers the rest as tails.
  const double reach = std::max(kReach, 2 * std::abs(to_u(zf)));
  const double inner_lo = std::max(u_lo, -reach), inner_hi = std::min(u_hi, reach);
  extra.push_back(inner_lo);
  extra.push_back(inner_hi);
  factory.add_points(p, extra);
  LocalPowerSolution out;
  ContinuousSolver solver(factory, settings);
  solver.set_interval(inner_lo, inner_hi);
  solver.set_tails(u_lo, u_hi, problem.degree % 2 == 0 ? problem.degree : 0);
  out.solution = solver.solve(p, backend, u, weights);
  for (size_t j = 0; j < out.solution.finite.support.size(); ++j) {
    out.support.push_back(mean + scale * p.point(out.solution.finite.support[j]));
    out.weights.push_back(out.solution.finite.weights[j]);
  }
  return out;
}

}  // namespace mb::lp
