#include "lp/fallback_backend.h"

#include "lp/glpk_backend.h"
#include "lp/kkt_checker.h"

namespace mb::lp {

namespace {

// The residual a GLPK answer may leave (its weights, rounded to double, leave ~1e-16).
constexpr double kFallbackResidual = 1e-14;

class FallbackBackend : public IntoBackend {
 public:
  explicit FallbackBackend(std::unique_ptr<Backend> primary) : primary_(std::move(primary)) {}
  std::string name() const override { return primary_->name(); }
  int max_functions() const override { return primary_->max_functions(); }
  void solve_into(const Problem& p, const WarmStart* at, Solution& s) override {
    primary_->solve_into(p, at, s);
    if (s.call != CallStatus::Ok || s.status == ProblemStatus::Optimal ||
        s.status == ProblemStatus::Infeasible)
      return;
    // GLPK's answer is accepted only if the KKT checker certifies it, with its first-order error
    // bound, and its weights reproduce the moments to double rounding. The bound alone is
    // one-sided: GLPK's answer 1.2e-10 to an LP whose optimum is 2.0e-7 (a basis feasible and
    // dual feasible in __float128) had a residual of 2e-12 and a bound of 5e-11. Otherwise the
    // primary's status stands.
    if (!glpk_) glpk_ = make_glpk_backend();
    Solution reference = glpk_->solve(p);
    const KktReport check = check_kkt(p, reference, kCertifiedError);
    if (reference.status == ProblemStatus::Optimal && check.ok &&
        check.error_bound <= kCertifiedError && check.primal_residual <= kFallbackResidual) {
      reference.iterations += s.iterations;
      s = std::move(reference);
      return;
    }
    // GLPK's "infeasible" is wrong by construction when a feasible distribution is known.
    if (reference.status == ProblemStatus::Infeasible && p.start_support.empty())
      s = std::move(reference);
  }

 private:
  std::unique_ptr<Backend> primary_, glpk_;
};

}  // namespace

std::unique_ptr<Backend> make_fallback_backend(std::unique_ptr<Backend> primary) {
  return std::make_unique<FallbackBackend>(std::move(primary));
}

}  // namespace mb::lp
