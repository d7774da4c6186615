#include "lp/blocker_bounds.h"

#include <glpk.h>

#include <stdexcept>

namespace mb {

namespace {

struct GlpkProblem {
  glp_prob* lp = glp_create_prob();
  ~GlpkProblem() { glp_delete_prob(lp); }
};

}  // namespace

BlockerBounds blocker_bounds(const lp::ProblemFactory& factory, std::span<const double> points,
                             std::span<const double> moments, double zs) {
  const int m = factory.rows() - 1, n = int(points.size());
  if (int(moments.size()) != m)
    throw std::invalid_argument("blocker_bounds: one moment per basis function");
  // Rows: T (1, b(z)) y - t T (1, b) = 0 (the mass and moment rows, transformed), the blocker
  // mass 1. Columns: y_i, then t.
  GlpkProblem p;
  glp_add_rows(p.lp, m + 2);
  for (int r = 1; r <= m + 1; ++r) glp_set_row_bnds(p.lp, r, GLP_FX, 0, 0);
  std::vector<double> column(size_t(m) + 1), rhs(size_t(m) + 1), raw{1.0};
  raw.insert(raw.end(), moments.begin(), moments.end());
  factory.transform(raw.data(), rhs.data());
  glp_set_row_bnds(p.lp, m + 2, GLP_FX, 1, 1);
  glp_add_cols(p.lp, n + 1);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  const auto add = [&](int row, int col, double v) {
    if (v == 0) return;
    ia.push_back(row), ja.push_back(col), ar.push_back(v);
  };
  for (int i = 0; i < n; ++i) {
    const int col = i + 1;
    glp_set_col_bnds(p.lp, col, GLP_LO, 0, 0);
    factory.column(points[size_t(i)], column.data());
    for (int r = 0; r <= m; ++r) add(r + 1, col, column[size_t(r)]);
    const bool blocker = points[size_t(i)] < zs;
    if (blocker) add(m + 2, col, 1);
    glp_set_obj_coef(p.lp, col, blocker ? points[size_t(i)] : 0);
  }
  glp_set_col_bnds(p.lp, n + 1, GLP_LO, 0, 0);
  for (int r = 0; r <= m; ++r) add(r + 1, n + 1, -rhs[size_t(r)]);
  glp_load_matrix(p.lp, int(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp params;
  glp_init_smcp(&params);
  params.msg_lev = GLP_MSG_OFF;
  params.presolve = GLP_OFF;
  // Regions of two or three surfaces make the LP highly degenerate, where GLPK's primal simplex
  // can stall; an answer not reached within the limit is no answer (`solved` false).
  params.it_lim = 20000;
  BlockerBounds out;
  double bound[2];
  for (int side = 0; side < 2; ++side) {
    glp_set_obj_dir(p.lp, side == 0 ? GLP_MIN : GLP_MAX);
    const int rc = glp_simplex(p.lp, &params);
    if (rc == GLP_EITLIM || rc == GLP_EFAIL || rc == GLP_ESING || rc == GLP_ECOND) return out;
    out.solved = true;
    if (rc != 0 || glp_get_status(p.lp) != GLP_OPT) return out;
    bound[side] = glp_get_obj_val(p.lp);
  }
  out.feasible = true;
  out.lo = bound[0], out.hi = bound[1];
  out.lps = 2;
  return out;
}

namespace {

// The blocker mass and mean depth of an LP's support; false when it holds no blocker.
bool support_mean(const lp::Problem& p, const lp::Solution& s, double zs, double& mean) {
  double mass = 0, sum = 0;
  for (size_t i = 0; i < s.support.size(); ++i) {
    const double z = p.point(s.support[i]);
    if (z < zs) mass += s.weights[i], sum += s.weights[i] * z;
  }
  if (!(mass > 0)) return false;
  mean = sum / mass;
  return true;
}

// Costs on the blockers: c (z - lambda), c = 1 for the least mean, -1 for the largest.
void set_objective(lp::Problem& p, double zs, double lambda, double c) {
  p.objective.resize(size_t(p.cols()));
  for (int j = 0; j < p.cols(); ++j) {
    const double z = p.point(j);
    p.objective[size_t(j)] = z < zs ? c * (z - lambda) : 0.0;
  }
}

bool solved(const lp::Solution& s) {
  return s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal;
}

}  // namespace

BlockerBounds blocker_bounds_dinkelbach(const lp::ProblemFactory& factory,
                                        std::span<const double> depths,
                                        std::span<const double> weights, double zs,
                                        lp::Backend& backend) {
  // Dinkelbach's steps converge superlinearly; the limit only guards against rounding cycling.
  constexpr int kMaxSteps = 50;
  // A step that lowers F(lambda) = min sum (z - lambda) w by less than this changes lambda by
  // rounding only.
  constexpr double kNoGain = 1e-15;
  BlockerBounds out;
  lp::Problem p = factory.from_distribution(depths, weights, zs);
  lp::Solution s;
  // A first distribution with blockers: the region's own, else the one of most blocker mass.
  double start = 0, mass = 0, sum = 0;
  for (size_t t = 0; t < depths.size(); ++t)
    if (depths[t] < zs) mass += weights[t], sum += weights[t] * depths[t];
  if (mass > 0) {
    start = sum / mass;
  } else {
    p.objective.assign(size_t(p.cols()), 0.0);
    for (int j = 0; j < p.cols(); ++j)
      if (p.point(j) < zs) p.objective[size_t(j)] = -1;
    backend.solve_into(p, nullptr, s);
    ++out.lps;
    if (!solved(s)) return out;
    out.solved = true;
    if (!support_mean(p, s, zs, start)) return out;
  }
  double bound[2];
  for (int side = 0; side < 2; ++side) {
    const double c = side == 0 ? 1.0 : -1.0;
    double lambda = start;
    for (int step = 0; step < kMaxSteps; ++step) {
      set_objective(p, zs, lambda, c);
      backend.solve_into(p, nullptr, s);
      ++out.lps;
      if (!solved(s)) return out;
      double next = 0;
      if (!(s.G < -kNoGain) || !support_mean(p, s, zs, next) || !(c * (next - lambda) < 0)) break;
      lambda = next;
    }
    bound[side] = lambda;
  }
  out.solved = out.feasible = true;
  out.lo = bound[0], out.hi = bound[1];
  return out;
}

}  // namespace mb
