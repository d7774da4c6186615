#include "lp/kkt_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mb::lp {

std::string KktReport::describe() const {
  char buffer[320];
  std::snprintf(
      buffer, sizeof buffer,
      "primal residual %.2e, negative weight %.2e, dual infeasibility %.2e, complementarity %.2e, "
      "duality gap %.2e, error bound %.2e: %s",
      primal_residual, negative_weight, dual_infeasibility, complementarity, duality_gap,
      error_bound, ok ? "ok" : "FAILED");
  return buffer;
}

KktReport check_kkt(const Problem& p, const Solution& s, double tolerance) {
  KktReport report;
  if (s.status != ProblemStatus::Optimal || s.duals.size() != size_t(p.rows) ||
      s.support.size() != s.weights.size())
    return report;
  std::vector<long double> residual(p.rhs.begin(), p.rhs.end());
  long double primal_objective = 0;
  for (size_t k = 0; k < s.support.size(); ++k) {
    int j = s.support[k];
    for (int r = 0; r < p.rows; ++r) residual[r] -= (long double)p.at(r, j) * s.weights[k];
    report.negative_weight = std::max(report.negative_weight, -s.weights[k]);
    primal_objective += p.cost(j) * (long double)s.weights[k];
  }
  long double moved = 0;
  for (int r = 0; r < p.rows; ++r) {
    report.primal_residual = std::max(report.primal_residual, double(std::abs(residual[r])));
    moved += std::abs((long double)s.duals[r] * residual[r]);
  }
  std::vector<long double> reduced(p.cols());
  for (int j = 0; j < p.cols(); ++j) {
    long double d = p.cost(j);
    for (int r = 0; r < p.rows; ++r) d -= (long double)s.duals[r] * p.at(r, j);
    reduced[j] = d;
    report.dual_infeasibility = std::max(report.dual_infeasibility, double(-d));
  }
  long double complementarity = 0;
  for (size_t k = 0; k < s.support.size(); ++k)
    complementarity += std::abs(s.weights[k] * reduced[s.support[k]]);
  report.complementarity = double(complementarity);
  long double dual_objective = 0;
  for (int r = 0; r < p.rows; ++r) dual_objective += (long double)s.duals[r] * p.rhs[r];
  report.duality_gap = double(std::abs(primal_objective - dual_objective));
  report.error_bound = double(moved + complementarity) + report.dual_infeasibility;
  report.ok = report.primal_residual <= tolerance && report.negative_weight <= tolerance &&
              report.dual_infeasibility <= tolerance && report.complementarity <= tolerance &&
              report.duality_gap <= tolerance &&
              std::abs(double(primal_objective) - s.G) <= tolerance;
  return report;
}

}  // namespace mb::lp
