#include "lp/exact_backend.h"

#include <gmp.h>

#include <mutex>
#include <vector>

extern "C" {
#include <qsopt_ex/QSopt_ex.h>
}

namespace mb::lp {

namespace {

// QSopt_ex's global data: started once per process, never cleared while a backend may still run.
std::mutex& library_lock() {
  static std::mutex lock;
  static std::once_flag started;
  std::call_once(started, [] { QSexactStart(); });
  return lock;
}

// An mpq_t that frees itself.
struct Rational {
  mpq_t q;
  Rational() { mpq_init(q); }
  explicit Rational(double v) {
    mpq_init(q);
    mpq_set_d(q, v);  // exact: every double is a dyadic rational
  }
  ~Rational() { mpq_clear(q); }
  Rational(const Rational&) = delete;
  Rational& operator=(const Rational&) = delete;
};

// n mpq_t that free themselves; data() is what QSopt_ex's array calls take.
class RationalArray {
 public:
  explicit RationalArray(size_t n) : values_(n) {
    for (auto& v : values_) mpq_init(&v);
  }
  ~RationalArray() {
    for (auto& v : values_) mpq_clear(&v);
  }
  RationalArray(const RationalArray&) = delete;
  RationalArray& operator=(const RationalArray&) = delete;
  mpq_t* data() { return reinterpret_cast<mpq_t*>(values_.data()); }
  mpq_ptr operator[](size_t i) { return &values_[i]; }

 private:
  std::vector<__mpq_struct> values_;
};

// A QSopt_ex problem that frees itself, also when an exception leaves the solve.
struct ExactProblem {
  mpq_QSprob lp = mpq_QScreate_prob("problem1", QS_MIN);
  ~ExactProblem() {
    if (lp) mpq_QSfree_prob(lp);
  }
  ExactProblem() = default;
  ExactProblem(const ExactProblem&) = delete;
  ExactProblem& operator=(const ExactProblem&) = delete;
};

class ExactBackend : public Backend {
 public:
  explicit ExactBackend(ExactRhs rhs) : rhs_(rhs) {}
  std::string name() const override { return "exact"; }
  int max_functions() const override { return kMaxColumnRows - 1; }

  Solution solve(const Problem& p) override {
    std::lock_guard<std::mutex> guard(library_lock());
    ExactProblem problem;
    mpq_QSprob lp = problem.lp;
    mpq_QSset_param(lp, QS_PARAM_SIMPLEX_DISPLAY, 0);
    Rational zero;  // QSopt_ex takes non-const mpq_t
    Rational infinity;
    mpq_set(infinity.q, mpq_ILL_MAXDOUBLE);
    for (int r = 0; r < p.rows; ++r) {
      Rational rhs(p.rhs[r]);
      if (rhs_ == ExactRhs::DistributionImage) exact_image_of_start(p, r, rhs.q);
      mpq_QSnew_row(lp, rhs.q, 'E', nullptr);
    }
    std::vector<int> rows(p.rows);
    for (int r = 0; r < p.rows; ++r) rows[r] = r;
    RationalArray column(size_t(p.rows));
    for (int j = 0; j < p.cols(); ++j) {
      for (int r = 0; r < p.rows; ++r) mpq_set_d(column[size_t(r)], p.at(r, j));
      Rational cost(p.cost(j));
      mpq_QSadd_col(lp, p.rows, rows.data(), column.data(), cost.q, zero.q, infinity.q, nullptr);
    }

    Solution s;
    s.engine = Engine::Exact;
    int status = 0;
    const int rc = QSexact_solver(lp, nullptr, nullptr, nullptr, PRIMAL_SIMPLEX, &status);
    if (rc != 0) {
      s.call = CallStatus::Failed;
      s.call_message = "QSexact_solver returned " + std::to_string(rc);
    } else if (status == QS_LP_OPTIMAL) {
      read_optimum(lp, p, s);
    } else {
      s.status = status == QS_LP_INFEASIBLE ? ProblemStatus::Infeasible : ProblemStatus::Unstable;
    }
    return s;
  }

 private:
  ExactRhs rhs_;

  // A problem built from a distribution (Problem::start_support) poses the moments of that
  // distribution: its double right-hand side is the rounding of sum_k w_k column_k, which for a
  // distribution on the boundary of the moment cone (one or two atoms of four power moments) no
  // distribution reproduces exactly. The exact sum keeps the distribution feasible, as the
  // problem means it (docs/lp-engine.md § The exact arbiter).
  static void exact_image_of_start(const Problem& p, int r, mpq_t rhs) {
    if (p.start_support.empty()) return;
    mpq_set_ui(rhs, 0, 1);
    Rational term, column;
    for (size_t k = 0; k < p.start_support.size(); ++k) {
      mpq_set_d(term.q, p.start_weights[k]);
      mpq_set_d(column.q, p.at(r, p.start_support[k]));
      mpq_mul(term.q, term.q, column.q);
      mpq_add(rhs, rhs, term.q);
    }
  }

  // G (the exact optimum, rounded to the nearest double), the support and the row duals.
  static void read_optimum(mpq_QSprob lp, const Problem& p, Solution& s) {
    s.status = ProblemStatus::Optimal;
    Rational objective;
    mpq_QSget_objval(lp, &objective.q);
    s.G = mpq_get_d(objective.q);
    RationalArray x(size_t(p.cols())), pi(size_t(p.rows));
    mpq_QSget_x_array(lp, x.data());
    mpq_QSget_pi_array(lp, pi.data());
    for (int j = 0; j < p.cols(); ++j)
      if (mpq_sgn(x[size_t(j)]) > 0)
        s.support.push_back(j), s.weights.push_back(mpq_get_d(x[size_t(j)]));
    s.duals.resize(p.rows);
    for (int r = 0; r < p.rows; ++r) s.duals[r] = mpq_get_d(pi[size_t(r)]);
  }
};

}  // namespace

std::unique_ptr<Backend> make_exact_backend(ExactRhs rhs) {
  return std::make_unique<ExactBackend>(rhs);
}

}  // namespace mb::lp
