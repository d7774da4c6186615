#include "continuous/moment_box.h"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mb::lp {

namespace {

// The stored values s(z) = offset + transform * b(z) at each point, row-major by stored value.
std::vector<double> stored_rows(const Basis& basis, const MomentBox& box,
                                std::span<const double> points) {
  const size_t m = basis.size(), n = points.size();
  std::vector<double> b(m * n), values(n);
  for (size_t j = 0; j < m; ++j) {
    basis[j].evaluate(points, values);
    std::copy(values.begin(), values.end(), b.begin() + j * n);
  }
  if (box.transform.size() == 0) return b;
  std::vector<double> s(m * n);
  for (size_t i = 0; i < m; ++i)
    for (size_t p = 0; p < n; ++p) {
      double v = box.offset.size() ? box.offset(Eigen::Index(i)) : 0.0;
      for (size_t j = 0; j < m; ++j)
        v += box.transform(Eigen::Index(i), Eigen::Index(j)) * b[j * n + p];
      s[i * n + p] = v;
    }
  return s;
}

// Each row's largest magnitude over the points (`s` row-major, n points a row).
std::vector<double> largest_magnitudes(const std::vector<double>& s, size_t rows, size_t n) {
  std::vector<double> largest(rows, 0.0);
  for (size_t i = 0; i < rows; ++i)
    for (size_t p = 0; p < n; ++p) largest[i] = std::max(largest[i], std::abs(s[i * n + p]));
  return largest;
}

// The LP's row scales: the largest magnitudes, 1 for a row that is zero at every point.
std::vector<double> row_scales(const std::vector<double>& s, size_t rows, size_t n) {
  std::vector<double> scale = largest_magnitudes(s, rows, n);
  for (double& x : scale)
    if (!(x > 0)) x = 1;
  return scale;
}

void check_box(const Basis& basis, const MomentBox& box) {
  const size_t m = basis.size();
  const bool shaped = box.transform.size() == 0 ||
                      (size_t(box.transform.rows()) == m && size_t(box.transform.cols()) == m &&
                       (box.offset.size() == 0 || size_t(box.offset.size()) == m));
  if (box.center.size() != m || box.tolerance.size() != m || !shaped)
    throw std::logic_error("moment box: " + std::to_string(box.center.size()) + " values and " +
                           std::to_string(box.tolerance.size()) + " tolerances for a basis of " +
                           std::to_string(m) + " functions");
}

constexpr int kIterationLimit = 20000;
// Phase 1's t (in units of each row's scale) that counts as inside the box: GLPK's bound
// tolerance, with which the box LP reads the same points.
constexpr double kElasticFeasible = 1e-12;

// GLPK's simplex for the box LP and its phase 1: bounds read to 1e-12 of a row's scale (the
// rows are scaled), reduced costs to 1e-10. An LP that does not settle (far points make columns
// of very different sizes) counts as unstable, and the exchange keeps its last certified round,
// instead of running on; an iteration limit, not a time limit, so that answers do not depend on
// the machine load.
glp_smcp box_simplex_parameters() {
  glp_smcp params;
  glp_init_smcp(&params);
  params.msg_lev = GLP_MSG_OFF;
  params.presolve = GLP_OFF;
  params.tol_bnd = 1e-12;
  params.tol_dj = 1e-10;
  params.it_lim = kIterationLimit;
  return params;
}

// A dual function in the basis from the duals of a box LP's rows: `constant` that of sum w = 1,
// pi[i] that of stored value i over its scale. phi(z) = constant + sum_i pi_i s_i(z), with
// s = transform b + offset when the box stores transformed values: c_0 = constant + pi . offset,
// c_j = (transform^T pi)_j.
std::vector<long double> dual_in_basis(const MomentBox& box, long double constant,
                                       const std::vector<long double>& pi) {
  const int m = int(pi.size());
  std::vector<long double> c(m + 1, 0.0L);
  c[0] = constant;
  for (int i = 0; i < m; ++i) {
    if (box.transform.size() == 0) {
      c[i + 1] = pi[i];
      continue;
    }
    if (box.offset.size()) c[0] += pi[i] * box.offset(i);
    for (int j = 0; j < m; ++j) c[j + 1] += pi[i] * box.transform(i, j);
  }
  return c;
}

// The box LP in GLPK: columns are the points' weights; row 1 is sum w = 1, row i + 2 the stored
// value i scaled by 1 / scale_i (its largest magnitude over the first points). Points added later
// enter as nonbasic columns at zero, so the last basis stays feasible: a warm start.
class BoxLp {
 public:
  // behind: minimise the mass strictly behind z_f instead (Problem::behind).
  BoxLp(const Basis& basis, const MomentBox& box, double zf, std::span<const double> points,
        bool behind = false)
      : basis_(basis), box_(box), zf_(zf), behind_(behind), lp_(glp_create_prob()) {
    check_box(basis, box);
    glp_term_out(GLP_OFF);
    const int m = int(basis.size());
    scale_ = row_scales(stored_rows(basis, box, points), size_t(m), points.size());
    glp_add_rows(lp_, m + 1);
    glp_set_row_bnds(lp_, 1, GLP_FX, 1, 1);
    for (int i = 0; i < m; ++i) {
      const double c = box.center[i] / scale_[i], e = box.tolerance[i] / scale_[i];
      glp_set_row_bnds(lp_, i + 2, e > 0 ? GLP_DB : GLP_FX, c - e, c + e);
    }
    glp_set_obj_dir(lp_, GLP_MIN);
    add_points(points);
  }
  ~BoxLp() { glp_delete_prob(lp_); }
  BoxLp(const BoxLp&) = delete;
  BoxLp& operator=(const BoxLp&) = delete;

  void add_points(std::span<const double> points) {
    if (points.empty()) return;
    const int m = int(basis_.size()), n = int(points.size());
    const std::vector<double> s = stored_rows(basis_, box_, points);
    const int first = glp_add_cols(lp_, n);
    std::vector<int> rows(m + 2);
    std::vector<double> values(m + 2);
    for (int p = 0; p < n; ++p) {
      rows[1] = 1, values[1] = 1;
      for (int i = 0; i < m; ++i)
        rows[i + 2] = i + 2, values[i + 2] = s[size_t(i) * n + p] / scale_[i];
      glp_set_mat_col(lp_, first + p, m + 1, rows.data(), values.data());
      glp_set_col_bnds(lp_, first + p, GLP_LO, 0, 0);
      glp_set_obj_coef(lp_, first + p, (behind_ ? points[p] > zf_ : points[p] < zf_) ? 1 : 0);
      points_.push_back(points[p]);
    }
  }

  // Optimal, Infeasible or Unstable (GLPK gave up).
  ProblemStatus solve() {
    glp_smcp params = box_simplex_parameters();
    if (!solved_) glp_std_basis(lp_);
    solved_ = true;
    int rc = glp_simplex(lp_, &params);
    if (rc != 0 || glp_get_status(lp_) == GLP_UNDEF) {
      glp_adv_basis(lp_, 0);
      params.meth = GLP_DUALP;
      rc = glp_simplex(lp_, &params);
    }
    const int status = glp_get_status(lp_);
    if (rc == 0 && status == GLP_OPT) return ProblemStatus::Optimal;
    if (status == GLP_NOFEAS || rc == GLP_ENOPFS) return ProblemStatus::Infeasible;
    return ProblemStatus::Unstable;
  }

  MomentBoxAnswer answer(ProblemStatus status) const {
    MomentBoxAnswer out;
    out.status = status;
    if (status != ProblemStatus::Optimal) return out;
    out.G = std::clamp(glp_get_obj_val(lp_), 0.0, 1.0);
    for (size_t j = 0; j < points_.size(); ++j) {
      const double w = glp_get_col_prim(lp_, int(j) + 1);
      if (w > 0) out.support.push_back(points_[j]), out.weights.push_back(w);
    }
    return out;
  }

  // The dual phi(z) = pi_1 + sum_i pi_i' s_i(z) (pi' = the row duals over the scales) in the
  // basis.
  std::vector<long double> coefficients() const {
    return dual_in_basis(box_, glp_get_row_dual(lp_, 1), scaled_duals());
  }

  // min over the box of E[phi] = pi_1 + sum_i (pi_i' c_i - |pi_i'| eps_i), and the magnitude of
  // its terms (for the rounding allowance).
  long double dual_objective(long double* magnitude) const {
    const std::vector<long double> pi = scaled_duals();
    long double v = glp_get_row_dual(lp_, 1);
    *magnitude = std::abs(v);
    for (size_t i = 0; i < pi.size(); ++i) {
      v += pi[i] * box_.center[i] - std::abs(pi[i]) * box_.tolerance[i];
      *magnitude += std::abs(pi[i]) * (std::abs(box_.center[i]) + box_.tolerance[i]);
    }
    return v;
  }

  // The largest E[b_k] of a distribution in the box (for the tails' delta (1 + E[z^n])).
  long double largest_moment(int k) const {
    if (box_.transform.size() == 0) return box_.center[k] + box_.tolerance[k];
    // Row k of the inverse transform: E[b_k] = row . (E[s] - offset).
    const Eigen::MatrixXd transposed = box_.transform.transpose();
    const Eigen::VectorXd row =
        transposed.partialPivLu().solve(Eigen::VectorXd::Unit(box_.transform.rows(), k));
    long double v = 0;
    for (size_t i = 0; i < box_.center.size(); ++i) {
      const double o = box_.offset.size() ? box_.offset(Eigen::Index(i)) : 0.0;
      v += row(Eigen::Index(i)) * (box_.center[i] - o) +
           std::abs(row(Eigen::Index(i))) * box_.tolerance[i];
    }
    return v;
  }

  const std::vector<double>& points() const { return points_; }

 private:
  std::vector<long double> scaled_duals() const {
    std::vector<long double> pi(basis_.size());
    for (size_t i = 0; i < pi.size(); ++i)
      pi[i] = (long double)glp_get_row_dual(lp_, int(i) + 2) / scale_[i];
    return pi;
  }

  const Basis& basis_;
  const MomentBox& box_;
  double zf_;
  bool behind_ = false;
  glp_prob* lp_;
  bool solved_ = false;
  std::vector<double> scale_, points_;
};

// Phase 1 of the box problem: minimise t over distributions on the points with
// c_i - eps_i - t scale_i <= E[s_i] <= c_i + eps_i + t scale_i, two rows per stored value (rows
// scaled as BoxLp's), t the first column. Points added later enter at zero weight: a warm start.
class ElasticLp {
 public:
  ElasticLp(const Basis& basis, const MomentBox& box, std::span<const double> points)
      : basis_(basis), box_(box), lp_(glp_create_prob()) {
    check_box(basis, box);
    glp_term_out(GLP_OFF);  // glp_adv_basis prints otherwise, into solve's JSON on stdout
    const int m = int(basis.size());
    scale_ = row_scales(stored_rows(basis, box, points), size_t(m), points.size());
    glp_add_rows(lp_, 2 * m + 1);
    glp_set_row_bnds(lp_, 1, GLP_FX, 1, 1);
    glp_add_cols(lp_, 1);
    std::vector<int> rows{0};
    std::vector<double> values{0};
    for (int i = 0; i < m; ++i) {
      const double c = box.center[i] / scale_[i], e = box.tolerance[i] / scale_[i];
      glp_set_row_bnds(lp_, i + 2, GLP_LO, c - e, 0);
      glp_set_row_bnds(lp_, m + i + 2, GLP_UP, 0, c + e);
      rows.push_back(i + 2), values.push_back(1);
      rows.push_back(m + i + 2), values.push_back(-1);
    }
    glp_set_mat_col(lp_, 1, 2 * m, rows.data(), values.data());
    glp_set_col_bnds(lp_, 1, GLP_LO, 0, 0);
    glp_set_obj_coef(lp_, 1, 1);
    glp_set_obj_dir(lp_, GLP_MIN);
    add_points(points);
  }
  ~ElasticLp() { glp_delete_prob(lp_); }
  ElasticLp(const ElasticLp&) = delete;
  ElasticLp& operator=(const ElasticLp&) = delete;

  void add_points(std::span<const double> points) {
    if (points.empty()) return;
    const int m = int(basis_.size()), n = int(points.size());
    const std::vector<double> s = stored_rows(basis_, box_, points);
    const int first = glp_add_cols(lp_, n);
    std::vector<int> rows(2 * m + 2);
    std::vector<double> values(2 * m + 2);
    for (int p = 0; p < n; ++p) {
      rows[1] = 1, values[1] = 1;
      for (int i = 0; i < m; ++i) {
        const double a = s[size_t(i) * n + p] / scale_[i];
        rows[i + 2] = i + 2, values[i + 2] = a;
        rows[m + i + 2] = m + i + 2, values[m + i + 2] = a;
      }
      glp_set_mat_col(lp_, first + p, 2 * m + 1, rows.data(), values.data());
      glp_set_col_bnds(lp_, first + p, GLP_LO, 0, 0);
      points_.push_back(points[p]);
    }
  }

  // The least t, or NaN when GLPK gives up.
  double solve() {
    const glp_smcp params = box_simplex_parameters();
    if (!solved_) glp_adv_basis(lp_, 0);
    solved_ = true;
    const int rc = glp_simplex(lp_, &params);
    if (rc != 0 || glp_get_status(lp_) != GLP_OPT) return std::numeric_limits<double>::quiet_NaN();
    return std::max(0.0, glp_get_obj_val(lp_));
  }

  // The points of positive weight.
  std::vector<double> support() const {
    std::vector<double> out;
    for (size_t j = 0; j < points_.size(); ++j)
      if (glp_get_col_prim(lp_, int(j) + 2) > 0) out.push_back(points_[j]);
    return out;
  }

  // The dual function psi(z) = y_1 + sum_i (y_i^lo + y_i^hi) s_i(z) / scale_i in the basis: a
  // point where psi > 0 lowers t (its reduced cost is -psi).
  std::vector<long double> coefficients() const {
    const int m = int(basis_.size());
    std::vector<long double> pi(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i)
      pi[size_t(i)] =
          ((long double)glp_get_row_dual(lp_, i + 2) + glp_get_row_dual(lp_, m + i + 2)) /
          scale_[i];
    return dual_in_basis(box_, glp_get_row_dual(lp_, 1), pi);
  }

  const std::vector<double>& points() const { return points_; }

 private:
  const Basis& basis_;
  const MomentBox& box_;
  glp_prob* lp_;
  bool solved_ = false;
  std::vector<double> scale_, points_;
};

// How far outside the cone the box's centre lies: minimise t with
// |E[s_i] - c_i| <= t max(|c_i|, eps_i) for every i, as two rows per value,
// E + t u >= c and E - t u <= c; t is the last column.
double relative_distance(const Basis& basis, const MomentBox& box, std::span<const double> points) {
  const int m = int(basis.size()), n = int(points.size());
  const std::vector<double> s = stored_rows(basis, box, points);
  const std::vector<double> scale = row_scales(s, size_t(m), size_t(n));
  glp_term_out(GLP_OFF);
  glp_prob* lp = glp_create_prob();
  glp_add_rows(lp, 2 * m + 1);
  glp_add_cols(lp, n + 1);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  const auto put = [&](int r, int c, double a) {
    ia.push_back(r), ja.push_back(c), ar.push_back(a);
  };
  for (int p = 0; p < n; ++p) {
    put(1, p + 1, 1);
    for (int i = 0; i < m; ++i) {
      const double a = s[size_t(i) * n + p] / scale[i];
      put(i + 2, p + 1, a);
      put(m + i + 2, p + 1, a);
    }
    glp_set_col_bnds(lp, p + 1, GLP_LO, 0, 0);
  }
  for (int i = 0; i < m; ++i) {
    const double unit = std::max(std::abs(box.center[i]), box.tolerance[i]) / scale[i];
    put(i + 2, n + 1, unit);
    put(m + i + 2, n + 1, -unit);
    glp_set_row_bnds(lp, i + 2, GLP_LO, box.center[i] / scale[i], 0);
    glp_set_row_bnds(lp, m + i + 2, GLP_UP, 0, box.center[i] / scale[i]);
  }
  glp_set_row_bnds(lp, 1, GLP_FX, 1, 1);
  glp_set_col_bnds(lp, n + 1, GLP_LO, 0, 0);
  glp_load_matrix(lp, int(ar.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_set_obj_dir(lp, GLP_MIN);
  glp_set_obj_coef(lp, n + 1, 1);
  glp_smcp params;
  glp_init_smcp(&params);
  params.msg_lev = GLP_MSG_OFF;
  params.presolve = GLP_OFF;
  params.tol_bnd = 1e-12;
  glp_adv_basis(lp, 0);
  const int rc = glp_simplex(lp, &params);
  const double t = rc == 0 && glp_get_status(lp) == GLP_OPT
                       ? glp_get_obj_val(lp)
                       : std::numeric_limits<double>::quiet_NaN();
  glp_delete_prob(lp);
  return t;
}

std::vector<double> problem_points(const Problem& problem) {
  std::vector<double> points(problem.cols());
  for (int j = 0; j < problem.cols(); ++j) points[j] = problem.point(j);
  return points;
}

}  // namespace

MomentBoxAnswer solve_moment_box(const Basis& basis, const MomentBox& box, double zf,
                                 std::span<const double> points, bool behind) {
  BoxLp lp(basis, box, zf, points, behind);
  MomentBoxAnswer out = lp.answer(lp.solve());
  if (out.status == ProblemStatus::Infeasible)
    out.relative_distance = relative_distance(basis, box, points);
  return out;
}

MomentBoxAnswer solve_moment_box(const ProblemFactory& factory, const Problem& problem,
                                 std::span<const double> tolerance) {
  const MomentBox box = MomentBox::of_moments(
      problem.moments, std::vector<double>(tolerance.begin(), tolerance.end()));
  return solve_moment_box(factory.basis(), box, problem.zf, problem_points(problem),
                          problem.behind);
}

std::vector<double> ulp_box(const ProblemFactory& factory, const Problem& problem, double ulps) {
  const std::vector<double> points = problem_points(problem);
  const MomentBox identity = MomentBox::of_moments(problem.moments, problem.moments);
  const std::vector<double> scale = largest_magnitudes(
      stored_rows(factory.basis(), identity, points), problem.moments.size(), points.size());
  std::vector<double> eps(problem.moments.size());
  constexpr double kUlp = std::numeric_limits<double>::epsilon();
  for (size_t k = 0; k < eps.size(); ++k)
    eps[k] = ulps * kUlp * std::max(std::abs(problem.moments[k]), scale[k]);
  return eps;
}

BoxPoints find_box_points(const Basis& basis, const MomentBox& box, const ContinuousDomain& domain,
                          std::span<const double> seed_points, const ContinuousSettings& settings) {
  std::vector<double> points(seed_points.begin(), seed_points.end());
  points.push_back(domain.lo);
  points.push_back(domain.hi);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  ElasticLp lp(basis, box, points);
  const int per_round =
      settings.points_per_round > 0 ? settings.points_per_round : 2 * int(basis.size() + 1);
  // The step is 0 everywhere (z_f below every point): the certificate then bounds psi itself.
  constexpr double kNoStep = -std::numeric_limits<double>::infinity();
  BoxPoints out;
  for (;;) {
    out.distance = lp.solve();
    ++out.rounds;
    if (std::isnan(out.distance)) return out;
    // Within GLPK's bound tolerance, as the box LP on these points will read it.
    if (out.distance <= kElasticFeasible) {
      out.found = true;
      out.points = lp.support();
      return out;
    }
    if (out.rounds >= settings.max_rounds) return out;
    const DualCertificate found =
        certify_dual(basis, lp.coefficients(), kNoStep, lp.points(), domain, settings);
    if (found.violators.empty()) return out;  // no point of the domain lowers t
    lp.add_points(std::span<const double>(found.violators.data(),
                                          std::min<size_t>(per_round, found.violators.size())));
  }
}

ContinuousBoxAnswer solve_moment_box_continuous(const Basis& basis, const MomentBox& box, double zf,
                                                const ContinuousDomain& domain,
                                                std::span<const double> seed_points,
                                                const ContinuousSettings& settings) {
  std::vector<double> points(seed_points.begin(), seed_points.end());
  for (double z : {domain.lo, domain.hi, zf})
    if (z >= domain.tail_lo && z <= domain.tail_hi) points.push_back(z);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  BoxLp lp(basis, box, zf, points);
  const int per_round =
      settings.points_per_round > 0 ? settings.points_per_round : 2 * int(basis.size() + 1);
  ContinuousBoxAnswer out;
  ProblemStatus status = lp.solve();
  for (;;) {
    if (out.rounds > 0 && status != ProblemStatus::Optimal) {
      // The finite LP failed after new points: the last certified round's bracket stands (points
      // added since only extend I).
      out.stalled = true;
      return out;
    }
    out.finite = lp.answer(status);
    if (!out.ok()) {
      if (status == ProblemStatus::Infeasible)
        out.finite.relative_distance = relative_distance(basis, box, lp.points());
      return out;
    }
    ++out.rounds;
    const std::vector<long double> c = lp.coefficients();
    const DualCertificate found = certify_dual(basis, c, zf, lp.points(), domain, settings);
    long double magnitude = 0;
    long double lower = lp.dual_objective(&magnitude) - found.violation;
    if (found.delta > 0) lower -= found.delta * (1 + lp.largest_moment(domain.even_degree - 1));
    out.lower = double(lower - DualCertificate::rounding() * magnitude);
    out.upper = out.finite.G;
    out.violation = double(found.violation);
    out.proven = found.proven;
    if (found.violators.empty() || out.width() <= settings.target_width ||
        out.rounds >= settings.max_rounds)
      return out;
    const size_t add = std::min<size_t>(per_round, found.violators.size());
    lp.add_points(std::span<const double>(found.violators.data(), add));
    out.points_added += int(add);
    status = lp.solve();
  }
}

}  // namespace mb::lp
