#include "continuous/discretized.h"

#include <limits>
#include <string>

#include "continuous/local_power.h"

namespace mb::lp {

int power_basis_degree(const Basis& basis) {
  for (size_t j = 0; j < basis.size(); ++j)
    if (basis[j].name() != (j == 0 ? std::string("z") : "z^" + std::to_string(j + 1))) return 0;
  return int(basis.size());
}

ContinuousSolution solve_discretized(const ProblemFactory& factory, Problem& problem,
                                     Backend& backend, std::span<const double> depths,
                                     std::span<const double> weights) {
  const Discretization& disc = factory.discretization();
  ContinuousSolution out;
  if (!disc.continuous) {
    out.finite = backend.solve(problem);
    out.upper = out.finite.G;
    out.lower = std::numeric_limits<double>::quiet_NaN();
    out.proven = false;
    return out;
  }
  const int degree = power_basis_degree(factory.basis());
  if (degree > 0 && !depths.empty()) {
    LocalPowerProblem local{degree, disc.lo, disc.hi, kContinuousSeedGrid};
    // The problem's own points beyond the distribution's depths and z_f (e.g. solve's --points).
    for (int j = problem.grid_size(); j < problem.cols(); ++j)
      if (problem.extra_atom.empty() || problem.extra_atom[j - problem.grid_size()] < 0)
        if (problem.point(j) != problem.zf) local.extra_points.push_back(problem.point(j));
    LocalPowerSolution s = solve_power_locally(local, depths, weights, problem.zf, backend);
    // The support as points of `problem`: appended where they are new.
    factory.add_points(problem, s.support);
    s.solution.finite.support.clear();
    for (double z : s.support)
      for (int j = 0; j < problem.cols(); ++j)
        if (problem.point(j) == z) {
          s.solution.finite.support.push_back(j);
          break;
        }
    return s.solution;
  }
  return ContinuousSolver(factory).solve(problem, backend, depths, weights);
}

}  // namespace mb::lp
