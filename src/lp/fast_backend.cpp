#include "lp/fast_backend.h"

#include <tuple>

#include "lp/exact_backend.h"
#include "lp/fallback_backend.h"
#include "lp/fast/certificates.h"
#include "lp/fast/driver.h"
#include "lp/fast/factorisation.h"
#include "lp/fast/iterations.h"
#include "lp/fast/pricing.h"
#include "lp/fast/refinement.h"
#include "lp/fast/simplex.h"
#include "lp/fast/starts.h"
#include "lp/glpk_backend.h"
#include "lp/row_count.h"
#include "lp/warm/bracket_shift.h"
#include "lp/warm/warm_start.h"
#include "util/error.h"

namespace mb::lp {

namespace {

using fast::FastSimplex;

class FastBackend : public IntoBackend {
 public:
  explicit FastBackend(const fast::SimplexSettings& settings) {
    std::apply([&](auto&... simplex) { (simplex.use(settings), ...); }, simplices_);
  }
  std::string name() const override { return "fast"; }
  int max_functions() const override { return kMaxRows - 1; }
  void solve_into(const Problem& p, const WarmStart* at, Solution& s) override {
    if (p.rows > kMaxRows) {
      s.reset();
      s.call = CallStatus::Failed;
      s.call_message =
          "the fast backend handles at most " + std::to_string(kMaxRows - 1) + " basis functions";
      return;
    }
    with_row_count<kMaxRows>(p.rows,
                             [&](auto rows) { std::get<rows() - 1>(simplices_).run(p, at, s); });
  }

  // One simplex per row count (each keeps the warm bases of its own problems).
  std::tuple<FastSimplex<1>, FastSimplex<2>, FastSimplex<3>, FastSimplex<4>, FastSimplex<5>,
             FastSimplex<6>, FastSimplex<7>, FastSimplex<8>>
      simplices_;
};

}  // namespace

std::unique_ptr<Backend> make_fast_backend(const fast::SimplexSettings& settings) {
  return std::make_unique<FastBackend>(settings);
}

const char* to_string(Engine engine) {
  return engine == Engine::Fast ? "fast" : engine == Engine::Glpk ? "glpk" : "exact";
}

const char* to_string(ProblemStatus status) {
  switch (status) {
    case ProblemStatus::Optimal:
      return "optimal";
    case ProblemStatus::Infeasible:
      return "infeasible";
    case ProblemStatus::IterationLimit:
      return "iteration_limit";
    case ProblemStatus::Unstable:
      return "unstable";
  }
  return "?";
}

std::vector<std::string> backend_names() {
  return {"fast", "glpk", "exact"};
}

std::unique_ptr<Backend> make_backend(const std::string& name) {
  if (name == "fast") return make_fallback_backend(make_fast_backend());
  if (name == "glpk") return make_glpk_backend();
  if (name == "exact") return make_exact_backend();
  std::string valid;
  for (const auto& n : backend_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("unknown LP backend '" + name + "'; valid: " + valid);
}

void check_backend_rows(const std::string& name, int functions, const std::string& what) {
  const int limit = make_backend(name)->max_functions();
  if (functions > limit)
    throw InputError(
        what + ": " + std::to_string(functions) + " basis functions, but LP backend '" + name +
        "' solves at most " + std::to_string(limit) +
        (name == "fast" ? " (lp.backend glpk takes up to " +
                              std::to_string(make_backend("glpk")->max_functions()) + ")"
                        : ""));
}

}  // namespace mb::lp
