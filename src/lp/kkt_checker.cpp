#include "lp/kkt_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mb::lp {

std::string KktReport::describe() const {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer,
                "primal residual %.2e, negative weight %.2e, dual infeasibility %.2e, complementarity %.2e, "
                "duality gap %.2e: %s",
                primal_residual, negative_weight, dual_infeasibility, complementarity, duality_gap,
                ok ? "ok" : "FAILED");
  return buffer;
}

KktReport check_kkt(const Problem& p, const Solution& s, double tolerance) {
  KktReport report;
  if (s.status != ProblemStatus::Optimal || s.duals.size() != size_t(p.rows) || s.support.size() != s.weights.size())
    return report;
  std::vector<double> residual(p.rhs);
  double primal_objective = 0;
  for (size_t k = 0; k < s.support.size(); ++k) {
    int j = s.support[k];
    for (int r = 0; r < p.rows; ++r) residual[r] -= p.at(r, j) * s.weights[k];
    report.negative_weight = std::max(report.negative_weight, -s.weights[k]);
    primal_objective += p.cost[j] * s.weights[k];
  }
  for (double v : residual) report.primal_residual = std::max(report.primal_residual, std::abs(v));
  std::vector<double> reduced(p.cols);
  for (int j = 0; j < p.cols; ++j) {
    double d = p.cost[j];
    for (int r = 0; r < p.rows; ++r) d -= s.duals[r] * p.at(r, j);
    reduced[j] = d;
    report.dual_infeasibility = std::max(report.dual_infeasibility, -d);
  }
  for (size_t k = 0; k < s.support.size(); ++k)
    report.complementarity = std::max(report.complementarity, std::abs(s.weights[k] * reduced[s.support[k]]));
  double dual_objective = 0;
  for (int r = 0; r < p.rows; ++r) dual_objective += s.duals[r] * p.rhs[r];
  report.duality_gap = std::abs(primal_objective - dual_objective) + std::abs(primal_objective - s.G);
  report.ok = report.primal_residual <= tolerance && report.negative_weight <= tolerance &&
              report.dual_infeasibility <= tolerance && report.complementarity <= tolerance &&
              report.duality_gap <= tolerance;
  return report;
}

}  // namespace mb::lp
