#pragma once
// The answer of an LP backend: a *call* status (did the solver run) kept apart from the
// *problem* status (what the LP is), as in HiGHS (DESIGN.md §Types).
#include <memory>
#include <string>
#include <vector>

#include "lp/problem.h"

namespace mb::lp {

enum class ProblemStatus { Optimal, Infeasible, Unstable };
enum class CallStatus { Ok, Failed };
const char* to_string(ProblemStatus status);

struct Solution {
  CallStatus call = CallStatus::Ok;
  std::string call_message;
  ProblemStatus status = ProblemStatus::Unstable;
  double G = 0;                   // the sharp lower bound (the LP optimum)
  std::vector<int> support;       // indices into Problem::points with positive weight
  std::vector<double> weights;    // same length as support
  // y, one per (transformed) row: a certificate of optimality. Long double because narrow kernels
  // (a sloped receiver covers depths 0.77..0.79) need |y| ~ 1e8, and y rounded to double then
  // misstates reduced costs by ~1e-8.
  std::vector<long double> duals;
  int iterations = 0;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  virtual Solution solve(const Problem& problem) = 0;
  // The same answer to within the certified 1e-9, possibly faster: `problem` continues a run of
  // neighbouring fragments (DESIGN.md §Performance shape), and the backend may start from the
  // optimal basis of the last problem it solved in the same `lane` (callers pass the fragment's
  // layer, so a surface continues from the same surface one texel back; lanes >= kWarmLanes
  // share the last one). The result then depends on the run, so callers that promise results
  // independent of the thread count must cut runs the same way on every schedule (kWarmStartRun)
  // and start each with `solve`, which forgets every lane. Backends without warm starts solve
  // from scratch.
  virtual Solution solve_next(const Problem& problem, int lane) {
    (void)lane;
    return solve(problem);
  }
};

constexpr int kWarmLanes = 8;
// Fragments per warm-start run: eval and sweep start a fresh run at every multiple of this
// fragment index, whatever thread gets it, so their results agree bit for bit.
constexpr size_t kWarmStartRun = 256;

// "fast" (our exact dense simplex) or "glpk" (the reference).
std::unique_ptr<Backend> make_backend(const std::string& name);
std::vector<std::string> backend_names();

}  // namespace mb::lp
