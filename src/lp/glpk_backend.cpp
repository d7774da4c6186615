#include "lp/glpk_backend.h"

#include <glpk.h>

#include <climits>
#include <vector>

namespace mb::lp {

namespace {

// Settings measured on this kind of machine (issue 4): presolve off; no scaling (scaling gave
// wrong answers); Dantzig pricing (fastest); an iteration limit, because without one about one LP
// in 5000 stalled, with a fallback to the dual simplex from GLPK's advanced basis.
class GlpkBackend : public Backend {
 public:
  explicit GlpkBackend(GlpkMode mode) : mode_(mode), lp_(glp_create_prob()) {
    glp_term_out(GLP_OFF);
    glp_init_smcp(&params_);
    params_.msg_lev = GLP_MSG_OFF;
    params_.meth = GLP_PRIMAL;
    params_.pricing = GLP_PT_STD;
    params_.presolve = GLP_OFF;
    // GLPK's default reduced-cost tolerance (1e-7) stops up to ~1e-8 short of the optimum on
    // these LPs (measured against our certified solutions); the reference must be good to 1e-9.
    params_.tol_dj = 1e-10;
    params_.tol_bnd = 1e-10;
  }
  ~GlpkBackend() override { glp_delete_prob(lp_); }
  std::string name() const override { return mode_ == GlpkMode::Exact ? "glpk_exact" : "glpk"; }
  int max_functions() const override { return kMaxColumnRows - 1; }

  Solution solve(const Problem& p) override {
    // The problem object is reused: erased, then filled with this LP.
    glp_erase_prob(lp_);
    glp_set_obj_dir(lp_, GLP_MIN);
    glp_add_rows(lp_, p.rows);
    glp_add_cols(lp_, p.cols());
    for (int r = 0; r < p.rows; ++r) glp_set_row_bnds(lp_, r + 1, GLP_FX, p.rhs[r], p.rhs[r]);
    for (int j = 0; j < p.cols(); ++j) {
      glp_set_col_bnds(lp_, j + 1, GLP_LO, 0.0, 0.0);
      glp_set_obj_coef(lp_, j + 1, p.cost(j));
    }
    size_t nonzeros = size_t(p.rows) * p.cols();
    ia_.assign(nonzeros + 1, 0);
    ja_.assign(nonzeros + 1, 0);
    ar_.assign(nonzeros + 1, 0.0);
    size_t k = 1;
    for (int r = 0; r < p.rows; ++r)
      for (int j = 0; j < p.cols(); ++j, ++k) ia_[k] = r + 1, ja_[k] = j + 1, ar_[k] = p.at(r, j);
    glp_load_matrix(lp_, int(nonzeros), ia_.data(), ja_.data(), ar_.data());

    Solution s;
    s.engine = Engine::Glpk;
    glp_std_basis(lp_);
    params_.meth = GLP_PRIMAL;
    // Optimal in ~30-140 pivots on dataset LPs; past 2000 GLPK is stalling (about one LP in 5000
    // without a limit) and the dual fallback below takes over.
    params_.it_lim = std::min(50 * (p.rows + p.cols()), 2000);
    int rc = glp_simplex(lp_, &params_);
    int iterations = glp_get_it_cnt(lp_);
    if (rc != 0 || glp_get_status(lp_) == GLP_UNDEF || glp_get_status(lp_) == GLP_FEAS) {
      // Iteration limit or numerical trouble: restart from an advanced basis with the dual
      // simplex falling back to primal (GLP_DUALP).
      glp_adv_basis(lp_, 0);
      params_.meth = GLP_DUALP;
      rc = glp_simplex(lp_, &params_);
      iterations += glp_get_it_cnt(lp_);
    }
    if (mode_ == GlpkMode::Exact) {
      // glp_exact starts from the basis the double simplex left, and only needs it valid; it has
      // no iteration limit of its own but obeys it_lim, which the double run set.
      if (rc != 0 && glp_warm_up(lp_) != 0) glp_std_basis(lp_);
      params_.it_lim = INT_MAX;
      rc = glp_exact(lp_, &params_);
      iterations += glp_get_it_cnt(lp_);
    }
    s.iterations = iterations;
    if (rc != 0 && rc != GLP_EITLIM && rc != GLP_ENOPFS && rc != GLP_ENODFS && rc != GLP_ESING &&
        rc != GLP_ECOND && rc != GLP_EOBJLL && rc != GLP_EOBJUL) {
      s.call = CallStatus::Failed;
      s.call_message = "glp_simplex returned " + std::to_string(rc);
      return s;
    }
    int status = glp_get_status(lp_);
    if (status == GLP_OPT) {
      s.status = ProblemStatus::Optimal;
    } else if (status == GLP_NOFEAS || rc == GLP_ENOPFS) {
      s.status = ProblemStatus::Infeasible;
      return s;
    } else {
      s.status = ProblemStatus::Unstable;
      return s;
    }
    s.G = glp_get_obj_val(lp_);
    for (int j = 0; j < p.cols(); ++j) {
      double w = glp_get_col_prim(lp_, j + 1);
      if (glp_get_col_stat(lp_, j + 1) == GLP_BS && w > 0)
        s.support.push_back(j), s.weights.push_back(w);
    }
    s.duals.resize(p.rows);
    for (int r = 0; r < p.rows; ++r) s.duals[r] = glp_get_row_dual(lp_, r + 1);
    return s;
  }

 private:
  GlpkMode mode_;
  glp_prob* lp_;
  glp_smcp params_;
  std::vector<int> ia_, ja_;
  std::vector<double> ar_;
};

}  // namespace

std::unique_ptr<Backend> make_glpk_backend(GlpkMode mode) {
  return std::make_unique<GlpkBackend>(mode);
}

}  // namespace mb::lp
