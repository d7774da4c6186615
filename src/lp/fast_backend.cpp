#include "lp/fast_backend.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "lp/glpk_backend.h"
#include "lp/kkt_checker.h"
#include "util/error.h"

namespace mb::lp {

namespace {

// Tolerances. Weights are probabilities (<= 1) and the rows are orthonormal, so absolute
// tolerances are meaningful: 1e-11 keeps the certified optimum well inside the 1e-9 promise.
constexpr double kFeasibilityTolerance = 1e-11;  // x_B >= -tol counts as feasible
constexpr double kOptimalityTolerance = 1e-11;   // reduced cost >= -tol counts as optimal
constexpr double kPivotTolerance = 1e-9;         // smallest |u_i| accepted as a pivot
constexpr double kPhase1Tolerance = 1e-10;       // residual artificial mass that means infeasible
// A fresh factorisation of a degenerate basis (boundary moment vectors: basic columns at zero
// level) reproduces x_B only to about cond(B) * 1e-16; on wide intervals ([-4, 5], powers to z^4)
// that reaches 1e-10. The certificate therefore accepts 1e-9, the accuracy promised for G.
constexpr double kCertifyTolerance = 1e-9;
constexpr int kRefactorInterval = 16;            // rank-1 updates between fresh inverses
constexpr int kDegenerateBeforeBland = 24;       // degenerate pivots in a row before Bland's rule

using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;

class FastSimplex {
 public:
  explicit FastSimplex(const Problem& p) : p_(p), k_(p.rows), n_(p.cols) {
    reduced_.resize(n_);
  }

  Solution run() {
    Solution s;
    // With a known feasible distribution, start phase 2 from it (no phase 1 at all).
    if (!p_.start_support.empty() && start_from_distribution()) {
      phase_ = 2;
      for (int attempt = 0; attempt < 3; ++attempt) {
        if (!iterate(s)) break;
        if (certify(s)) return s;
        if (!dual_cleanup(s)) break;
        if (certify(s)) return s;
      }
      s = Solution();
    }
    start_with_artificials();
    // Phase 1: minimise the artificial mass.
    phase_ = 1;
    if (!iterate(s)) return unstable(s);
    double artificial = 0;
    for (int i = 0; i < k_; ++i)
      if (basis_[i] >= n_) artificial += x_[i];
    if (artificial > kPhase1Tolerance) {
      s.status = ProblemStatus::Infeasible;
      return s;
    }
    if (!drive_out_artificials()) return unstable(s);
    phase_ = 2;
    // Phase 2, then certification from a fresh factorisation; a failed certificate resumes.
    for (int attempt = 0; attempt < 3; ++attempt) {
      if (!iterate(s)) return unstable(s);
      if (certify(s)) return s;
      if (!dual_cleanup(s)) return unstable(s);
      if (certify(s)) return s;
    }
    return unstable(s);
  }

 private:
  Solution& unstable(Solution& s) {
    s.status = ProblemStatus::Unstable;
    return s;
  }

  double column(int j, int r) const {
    if (j < n_) return p_.at(r, j);
    return r == j - n_ ? artificial_sign_[r] : 0.0;
  }
  double cost(int j) const {
    if (phase_ == 1) return j >= n_ ? 1.0 : 0.0;
    return j >= n_ ? 0.0 : double(p_.cost[j]);
  }

  void start_with_artificials() {
    for (int r = 0; r < k_; ++r) {
      artificial_sign_[r] = p_.rhs[r] >= 0 ? 1.0 : -1.0;
      basis_[r] = n_ + r;
      x_[r] = std::abs(p_.rhs[r]);
    }
    binv_ = SmallMatrix::Zero(k_, k_);
    for (int r = 0; r < k_; ++r) binv_(r, r) = artificial_sign_[r];
    updates_ = 0;
  }

  // Carathéodory: reduce the known distribution to affinely independent support (moving along
  // null vectors of its columns until a weight reaches zero), then complete the basis with grid
  // columns at zero level that keep it nonsingular.
  bool start_from_distribution() {
    std::vector<int> support = p_.start_support;
    std::vector<double> weights = p_.start_weights;
    for (int guard = 0; guard < 64; ++guard) {
      const int s = int(support.size());
      Eigen::MatrixXd a(k_, s);
      for (int c = 0; c < s; ++c)
        for (int r = 0; r < k_; ++r) a(r, c) = p_.at(r, support[c]);
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
      lu.setThreshold(1e-12);
      if (lu.rank() == s) break;
      Eigen::VectorXd v = lu.kernel().col(0);
      if (v.maxCoeff() <= 0) v = -v;
      double t = std::numeric_limits<double>::infinity();
      for (int c = 0; c < s; ++c)
        if (v(c) > 0) t = std::min(t, weights[c] / v(c));
      std::vector<int> next_support;
      std::vector<double> next_weights;
      for (int c = 0; c < s; ++c) {
        double w = weights[c] - t * v(c);
        if (w > 1e-15) next_support.push_back(support[c]), next_weights.push_back(w);
      }
      support.swap(next_support);
      weights.swap(next_weights);
    }
    if (int(support.size()) > k_) return false;
    int count = 0;
    for (int j : support) basis_[count++] = j;
    // Complete with columns spread over I, each kept only if it raises the rank.
    for (int stride = std::max(1, n_ / (2 * k_)), j = 0; count < k_ && j < n_ * 2; j += stride) {
      int candidate = (j % n_ + j / n_) % n_;
      if (std::find(basis_, basis_ + count, candidate) != basis_ + count) continue;
      Eigen::MatrixXd a(k_, count + 1);
      for (int c = 0; c <= count; ++c)
        for (int r = 0; r < k_; ++r) a(r, c) = p_.at(r, c < count ? basis_[c] : candidate);
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
      lu.setThreshold(1e-9);
      if (lu.rank() == count + 1) basis_[count++] = candidate;
    }
    if (count < k_ || !refactor()) return false;
    for (int i = 0; i < k_; ++i)
      if (x_[i] < -kCertifyTolerance) return false;
    return true;
  }

  bool refactor() {
    SmallMatrix b(k_, k_);
    for (int i = 0; i < k_; ++i)
      for (int r = 0; r < k_; ++r) b(r, i) = column(basis_[i], r);
    Eigen::FullPivLU<SmallMatrix> lu(b);
    // Eigen's default singularity threshold (size * epsilon) rejects the merely ill-conditioned
    // bases of tiny-valued columns (z^6 near 0); 1e-13 of the largest pivot still catches rank loss.
    lu.setThreshold(1e-13);
    if (!lu.isInvertible()) return false;
    binv_ = lu.inverse();
    for (int i = 0; i < k_; ++i) {
      double v = 0;
      for (int r = 0; r < k_; ++r) v += binv_(i, r) * p_.rhs[r];
      x_[i] = v;
    }
    updates_ = 0;
    return true;
  }

  // y = B^{-T} c_B, then reduced costs of all structural columns in one vectorised pass.
  void price() {
    for (int r = 0; r < k_; ++r) {
      double v = 0;
      for (int i = 0; i < k_; ++i) v += cost(basis_[i]) * binv_(i, r);
      y_[r] = v;
    }
    double* d = reduced_.data();
    if (phase_ == 1) {
      std::fill(d, d + n_, 0.0);
    } else {
      for (int j = 0; j < n_; ++j) d[j] = p_.cost[j];
    }
    for (int r = 0; r < k_; ++r) {
      const double* row = &p_.matrix[size_t(r) * n_];
      const double yr = y_[r];
      for (int j = 0; j < n_; ++j) d[j] -= yr * row[j];
    }
  }

  int choose_entering(bool bland) const {
    int best = -1;
    double best_value = -kOptimalityTolerance;
    for (int j = 0; j < n_; ++j) {
      if (reduced_[j] < best_value) {
        best = j;
        if (bland) return j;
        best_value = reduced_[j];
      }
    }
    return best;
  }

  // One simplex run to optimality for the current phase. False on numerical failure.
  bool iterate(Solution& s) {
    int degenerate = 0;
    const int limit = 20 * (n_ + k_);
    for (int guard = 0; guard < limit; ++guard) {
      if (updates_ >= kRefactorInterval && !refactor()) return false;
      price();
      bool bland = degenerate >= kDegenerateBeforeBland;
      int entering = choose_entering(bland);
      if (entering < 0) return true;
      double u[kMaxRows];
      column_in_basis(entering, u);
      // Harris ratio test: a relaxed bound first, then the largest pivot within it.
      double theta_max = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k_; ++i)
        if (u[i] > kPivotTolerance) theta_max = std::min(theta_max, (x_[i] + kFeasibilityTolerance) / u[i]);
      if (!std::isfinite(theta_max)) return false;  // unbounded: impossible with sum w = 1
      int leave = -1;
      // (theta_max < 0 only when a basic value is already below -tolerance: step 0 on it.)
      double best_pivot = 0;
      for (int i = 0; i < k_; ++i) {
        if (u[i] <= kPivotTolerance || x_[i] / u[i] > std::max(theta_max, 0.0)) continue;
        bool better = bland ? (leave < 0 || basis_[i] < basis_[leave]) : u[i] > best_pivot;
        if (better) leave = i, best_pivot = u[i];
      }
      double theta = std::max(x_[leave], 0.0) / u[leave];
      degenerate = theta == 0 ? degenerate + 1 : 0;
      // Basic values may go slightly negative (Harris); the certificate judges the final basis.
      for (int i = 0; i < k_; ++i) x_[i] -= theta * u[i];
      x_[leave] = theta;
      pivot(leave, entering, u);
      ++s.iterations;
    }
    return false;
  }

  // u = B^{-1} a_j, the entering column in basis coordinates (shared by primal and dual steps).
  void column_in_basis(int j, double* u) const {
    for (int i = 0; i < k_; ++i) {
      double v = 0;
      for (int r = 0; r < k_; ++r) v += binv_(i, r) * p_.at(r, j);
      u[i] = v;
    }
  }

  // Product-form update of the explicit inverse: column `entering` replaces basis row `leave`.
  void pivot(int leave, int entering, const double* u) {
    double p = u[leave];
    for (int r = 0; r < k_; ++r) binv_(leave, r) /= p;
    for (int i = 0; i < k_; ++i) {
      if (i == leave || u[i] == 0) continue;
      for (int r = 0; r < k_; ++r) binv_(i, r) -= u[i] * binv_(leave, r);
    }
    basis_[leave] = entering;
    ++updates_;
  }

  // Dual simplex steps from a dual feasible but slightly primal infeasible basis, which
  // ill-conditioned instances (z^3, z^6 near z = 0) can end the primal phase with: the most
  // negative basic variable leaves, the entering column keeps every reduced cost >= 0.
  bool dual_cleanup(Solution& s) {
    for (int step = 0; step < 4 * k_ + 16; ++step) {
      if (!refactor()) return false;
      int leave = -1;
      double worst = -kCertifyTolerance;
      for (int i = 0; i < k_; ++i)
        if (x_[i] < worst) leave = i, worst = x_[i];
      if (leave < 0) return true;
      price();
      // Dual Harris ratio test: a relaxed bound on the step in the duals, then the largest
      // |alpha| within it, so that the new basis stays well conditioned.
      std::vector<double>& alpha = alpha_;
      alpha.resize(n_);
      double alpha_max = 0;
      for (int j = 0; j < n_; ++j) {
        double a = 0;
        for (int r = 0; r < k_; ++r) a += binv_(leave, r) * p_.at(r, j);
        alpha[j] = a;
        alpha_max = std::max(alpha_max, -a);
      }
      const double pivot_floor = std::max(kPivotTolerance, 1e-7 * alpha_max);
      double bound = std::numeric_limits<double>::infinity();
      for (int j = 0; j < n_; ++j)
        if (alpha[j] < -pivot_floor) bound = std::min(bound, (reduced_[j] + kOptimalityTolerance) / -alpha[j]);
      int entering = -1;
      double best_alpha = 0;
      for (int j = 0; j < n_; ++j)
        if (alpha[j] < -pivot_floor && reduced_[j] / -alpha[j] <= bound && -alpha[j] > best_alpha)
          entering = j, best_alpha = -alpha[j];
      if (entering < 0) return false;  // would mean primal infeasible: not for a feasible LP
      double u[kMaxRows];
      column_in_basis(entering, u);
      double theta = x_[leave] / u[leave];
      for (int i = 0; i < k_; ++i) x_[i] -= theta * u[i];
      x_[leave] = theta;
      pivot(leave, entering, u);
      ++s.iterations;
    }
    return false;
  }

  // After phase 1 every artificial left in the basis sits at zero; pivot each out on the
  // structural column with the largest entry in its row of B^{-1} A (rows are independent after
  // orthonormalisation, so one exists).
  bool drive_out_artificials() {
    for (int i = 0; i < k_; ++i) {
      if (basis_[i] < n_) continue;
      int best = -1;
      double best_value = 1e-7;
      for (int j = 0; j < n_; ++j) {
        if (std::find(basis_, basis_ + k_, j) != basis_ + k_) continue;
        double v = 0;
        for (int r = 0; r < k_; ++r) v += binv_(i, r) * p_.at(r, j);
        if (std::abs(v) > best_value) best = j, best_value = std::abs(v);
      }
      if (best < 0) return false;
      basis_[i] = best;
      if (!refactor()) return false;
    }
    return refactor();
  }

  // Fresh inverse, x_B and y: accept only a primal and dual feasible basis.
  bool certify(Solution& s) {
    if (!refactor()) return false;
    for (int i = 0; i < k_; ++i)
      if (x_[i] < -kCertifyTolerance) return false;
    price();
    for (int j = 0; j < n_; ++j)
      if (reduced_[j] < -kCertifyTolerance) return false;
    s.status = ProblemStatus::Optimal;
    s.G = 0;
    s.support.clear();
    s.weights.clear();
    for (int i = 0; i < k_; ++i) {
      double w = std::max(x_[i], 0.0);
      s.G += p_.cost[basis_[i]] * w;
      if (w > 0) s.support.push_back(basis_[i]), s.weights.push_back(w);
    }
    s.duals.assign(y_, y_ + k_);
    return true;
  }

  const Problem& p_;
  const int k_, n_;
  int phase_ = 1;
  int basis_[kMaxRows];
  double x_[kMaxRows], y_[kMaxRows], artificial_sign_[kMaxRows];
  SmallMatrix binv_;
  int updates_ = 0;
  std::vector<double> reduced_, alpha_;
};

class FastBackend : public Backend {
 public:
  std::string name() const override { return "fast"; }
  Solution solve(const Problem& p) override {
    if (p.rows > kMaxRows) {
      Solution s;
      s.call = CallStatus::Failed;
      s.call_message = "the fast backend handles at most " + std::to_string(kMaxRows - 1) + " basis functions";
      return s;
    }
    Solution s = FastSimplex(p).run();
    if (s.status != ProblemStatus::Unstable) return s;
    // The rare instance our simplex cannot certify (ill-conditioned columns such as z^3, z^6
    // near z = 0, where neighbouring columns differ by 1e-10) goes to GLPK, and its answer is
    // accepted only if the independent KKT checker certifies it; otherwise it stays unstable.
    if (!glpk_) glpk_ = make_glpk_backend();
    Solution reference = glpk_->solve(p);
    ++fallbacks_;
    if (reference.status == ProblemStatus::Optimal && check_kkt(p, reference, kCertifyTolerance).ok) {
      reference.iterations += s.iterations;
      return reference;
    }
    if (reference.status == ProblemStatus::Infeasible) return reference;
    return s;
  }
  int fallbacks() const { return fallbacks_; }

 private:
  std::unique_ptr<Backend> glpk_;
  int fallbacks_ = 0;
};

}  // namespace

std::unique_ptr<Backend> make_fast_backend() { return std::make_unique<FastBackend>(); }

const char* to_string(ProblemStatus status) {
  switch (status) {
    case ProblemStatus::Optimal: return "optimal";
    case ProblemStatus::Infeasible: return "infeasible";
    case ProblemStatus::Unstable: return "unstable";
  }
  return "?";
}

std::vector<std::string> backend_names() { return {"fast", "glpk"}; }

std::unique_ptr<Backend> make_backend(const std::string& name) {
  if (name == "fast") return make_fast_backend();
  if (name == "glpk") return make_glpk_backend();
  throw InputError("unknown LP backend '" + name + "'; valid: fast, glpk");
}

}  // namespace mb::lp
