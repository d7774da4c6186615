#include "lp/moment_box.h"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mb::lp {

namespace {

// The raw values b_j(z_i) of the problem's points, row-major, and each row's largest magnitude.
struct RawRows {
  int rows = 0, cols = 0;
  std::vector<double> values, scale;
};

RawRows raw_rows(const ProblemFactory& factory, const Problem& problem) {
  RawRows r;
  const Basis& basis = factory.basis();
  r.rows = int(basis.size());
  r.cols = problem.cols();
  r.values.resize(size_t(r.rows) * r.cols);
  r.scale.assign(r.rows, 0.0);
  std::vector<double> points(r.cols), values(r.cols);
  for (int j = 0; j < r.cols; ++j) points[j] = problem.point(j);
  for (int k = 0; k < r.rows; ++k) {
    basis[k].evaluate(points, values);
    for (int j = 0; j < r.cols; ++j) {
      r.values[size_t(k) * r.cols + j] = values[j];
      r.scale[k] = std::max(r.scale[k], std::abs(values[j]));
    }
    if (r.scale[k] == 0) r.scale[k] = 1;
  }
  return r;
}

// One GLPK problem: columns are the points' weights; row 1 is sum w = 1, rows 2.. the scaled
// moment rows (the distance model adds its own column and rows afterwards).
class GlpkModel {
 public:
  GlpkModel() : lp_(glp_create_prob()) { glp_term_out(GLP_OFF); }
  ~GlpkModel() { glp_delete_prob(lp_); }
  glp_prob* get() { return lp_; }
  int solve() {
    glp_smcp params;
    glp_init_smcp(&params);
    params.msg_lev = GLP_MSG_OFF;
    params.presolve = GLP_OFF;
    params.tol_bnd = 1e-12;
    params.tol_dj = 1e-10;
    glp_std_basis(lp_);
    int rc = glp_simplex(lp_, &params);
    if (rc != 0 || glp_get_status(lp_) == GLP_UNDEF) {
      glp_adv_basis(lp_, 0);
      params.meth = GLP_DUALP;
      rc = glp_simplex(lp_, &params);
    }
    return rc;
  }

 private:
  glp_prob* lp_;
};

void load(glp_prob* lp, const RawRows& raw) {
  const int n = raw.cols;
  glp_add_rows(lp, raw.rows + 1);
  glp_add_cols(lp, n);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  for (int j = 0; j < raw.cols; ++j) {
    ia.push_back(1), ja.push_back(j + 1), ar.push_back(1);
    for (int k = 0; k < raw.rows; ++k)
      ia.push_back(k + 2), ja.push_back(j + 1),
          ar.push_back(raw.values[size_t(k) * raw.cols + j] / raw.scale[k]);
  }
  glp_load_matrix(lp, int(ar.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_set_row_bnds(lp, 1, GLP_FX, 1, 1);
  for (int j = 1; j <= n; ++j) glp_set_col_bnds(lp, j, GLP_LO, 0, 0);
}

}  // namespace

std::vector<double> ulp_box(const ProblemFactory& factory, const Problem& problem, double ulps) {
  const RawRows raw = raw_rows(factory, problem);
  std::vector<double> eps(problem.moments.size());
  constexpr double kUlp = std::numeric_limits<double>::epsilon();
  for (size_t k = 0; k < eps.size(); ++k)
    eps[k] = ulps * kUlp * std::max(std::abs(problem.moments[k]), raw.scale[k]);
  return eps;
}

MomentBoxAnswer solve_moment_box(const ProblemFactory& factory, const Problem& problem,
                                 std::span<const double> tolerance) {
  const RawRows raw = raw_rows(factory, problem);
  MomentBoxAnswer out;
  {
    GlpkModel model;
    glp_prob* lp = model.get();
    load(lp, raw);
    glp_set_obj_dir(lp, GLP_MIN);
    for (int j = 0; j < raw.cols; ++j) glp_set_obj_coef(lp, j + 1, problem.cost(j));
    for (int k = 0; k < raw.rows; ++k) {
      const double b = problem.moments[k] / raw.scale[k], e = tolerance[k] / raw.scale[k];
      if (e > 0)
        glp_set_row_bnds(lp, k + 2, GLP_DB, b - e, b + e);
      else
        glp_set_row_bnds(lp, k + 2, GLP_FX, b, b);
    }
    const int rc = model.solve();
    const int status = glp_get_status(lp);
    if (rc == 0 && status == GLP_OPT) {
      out.status = ProblemStatus::Optimal;
      out.G = std::clamp(glp_get_obj_val(lp), 0.0, 1.0);
      for (int j = 0; j < raw.cols; ++j) {
        const double w = glp_get_col_prim(lp, j + 1);
        if (w > 0) out.support.push_back(problem.point(j)), out.weights.push_back(w);
      }
      return out;
    }
    if (status != GLP_NOFEAS && rc != GLP_ENOPFS) return out;  // unstable
  }
  // How far outside: minimise t with |E[b_k] - b_k| <= t max(|b_k|, eps_k) for every k, as two
  // rows per moment, E + t u >= b (rows 2..m+1) and E - t u <= b (rows m+2..2m+1); t is the last
  // column.
  out.status = ProblemStatus::Infeasible;
  GlpkModel model;
  glp_prob* lp = model.get();
  std::vector<double> unit(raw.rows);
  for (int k = 0; k < raw.rows; ++k)
    unit[k] = std::max(std::abs(problem.moments[k]), tolerance[k]) / raw.scale[k];
  // Weights and bounds as for the box; then t, the extra rows and the whole matrix anew.
  load(lp, raw);
  glp_add_cols(lp, 1);
  glp_set_col_bnds(lp, raw.cols + 1, GLP_LO, 0, 0);
  const int lower_rows = glp_add_rows(lp, raw.rows);
  std::vector<int> all_i{0}, all_j{0};
  std::vector<double> all_a{0};
  const auto put = [&](int r, int c, double a) {
    all_i.push_back(r), all_j.push_back(c), all_a.push_back(a);
  };
  for (int j = 0; j < raw.cols; ++j) {
    put(1, j + 1, 1);
    for (int k = 0; k < raw.rows; ++k) {
      const double a = raw.values[size_t(k) * raw.cols + j] / raw.scale[k];
      put(k + 2, j + 1, a);
      put(lower_rows + k, j + 1, a);
    }
  }
  for (int k = 0; k < raw.rows; ++k) {
    put(k + 2, raw.cols + 1, unit[k]);
    put(lower_rows + k, raw.cols + 1, -unit[k]);
  }
  glp_load_matrix(lp, int(all_a.size()) - 1, all_i.data(), all_j.data(), all_a.data());
  for (int k = 0; k < raw.rows; ++k) {
    const double b = problem.moments[k] / raw.scale[k];
    glp_set_row_bnds(lp, k + 2, GLP_LO, b, 0);
    glp_set_row_bnds(lp, lower_rows + k, GLP_UP, 0, b);
  }
  glp_set_obj_dir(lp, GLP_MIN);
  glp_set_obj_coef(lp, raw.cols + 1, 1);
  if (model.solve() == 0 && glp_get_status(lp) == GLP_OPT)
    out.relative_distance = glp_get_obj_val(lp);
  else
    out.relative_distance = std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace mb::lp
