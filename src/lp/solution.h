#pragma once
// The answer of an LP backend: a *call* status (did the solver run) kept apart from the
// *problem* status (what the LP is), as in HiGHS (DESIGN.md §Types).
#include <memory>
#include <string>
#include <vector>

#include "lp/problem.h"

namespace mb::lp {

// Unstable: numerical trouble (no basis could be certified); IterationLimit: the simplex stopped at
// its iteration limit (a stalling, ill-conditioned LP). Neither is an answer.
enum class ProblemStatus { Optimal, Infeasible, IterationLimit, Unstable };
// Every Optimal answer's G is within this of the LP's optimum (REFERENCE.md §2): the fast backend
// proves it with a certificate, and accepts a GLPK answer only with the KKT checker's.
constexpr double kCertifiedError = 1e-9;
enum class CallStatus { Ok, Failed };
const char* to_string(ProblemStatus status);

// Which solver produced an answer: the fast backend hands the rare LP its simplex cannot certify
// to GLPK (accepted only with an independent certificate), so a comparison of the two backends
// must know which answers are GLPK's own.
enum class Engine { Fast, Glpk };
const char* to_string(Engine engine);

struct Solution {
  CallStatus call = CallStatus::Ok;
  std::string call_message;
  ProblemStatus status = ProblemStatus::Unstable;
  double G = 0;                 // the sharp lower bound (the LP optimum)
  std::vector<int> support;     // indices into Problem::points with positive weight
  std::vector<double> weights;  // same length as support
  // y, one per (transformed) row: a certificate of optimality. Long double because narrow kernels
  // (a sloped receiver covers depths 0.77..0.79) need |y| ~ 1e8, and y rounded to double then
  // misstates reduced costs by ~1e-8.
  std::vector<long double> duals;
  int iterations = 0;
  Engine engine = Engine::Fast;
  // A fresh Solution again, with the vectors' storage kept (Backend::solve_into).
  void reset() {
    call = CallStatus::Ok;
    call_message.clear();
    status = ProblemStatus::Unstable;
    G = 0;
    support.clear();
    weights.clear();
    duals.clear();
    iterations = 0;
    engine = Engine::Fast;
  }
};

// Where a fragment sits in its warm-start run (DESIGN.md §Performance shape, extended to two
// dimensions): its layer, so that it can continue from the same layer of the texel to the left
// (the last problem solved in that lane), and its texel column, so that it can continue from any
// layer of the texel above or above to the right (the last problems solved in those columns; the
// run goes in raster order); -1: no column memory.
struct WarmPosition {
  int layer = 0;
  int column = -1;
  // The texel row (-1: unknown): with it and the column, a kernel column of a remembered basis maps
  // to the tap that sees the same texel, so that the same depth (the same column) comes back.
  int row = -1;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // The most basis functions (rows - 1) this backend solves; callers check it before any work.
  virtual int max_functions() const = 0;
  virtual Solution solve(const Problem& problem) = 0;
  // The same answer to within the certified 1e-9, possibly faster: `problem` continues a run of
  // neighbouring fragments in raster order, and the backend may start from the optimal bases of
  // the problems it solved last at the texel to the left (same layer; layers >= kWarmLanes share
  // the last lane) and at the texels above and above to the right (`at`). The result then depends
  // on the run, so callers that promise results independent of the thread count must cut runs the
  // same way on every schedule (warm_run_of) and start each with `solve`, which forgets every
  // basis. Backends without warm starts solve from scratch.
  virtual Solution solve_next(const Problem& problem, WarmPosition at) {
    (void)at;
    return solve(problem);
  }
  // solve (at == nullptr) or solve_next, into `out`, whose storage a backend may reuse: the loops
  // over millions of LPs (sweep, eval's lp:) then allocate nothing per LP (three allocations and
  // frees an LP otherwise).
  virtual void solve_into(const Problem& problem, const WarmPosition* at, Solution& out) {
    out = at ? solve_next(problem, *at) : solve(problem);
  }
};

constexpr int kWarmLanes = 8;
// Shadow-map rows per warm-start run: eval and sweep start a fresh run at every band of this many
// rows, whatever thread gets it, so their results agree bit for bit. Within a band every row but
// the first has the row above to start from; bands of 8 rows keep 64 runs per 512-row view for
// the threads to share.
constexpr int kWarmRunRows = 8;
inline int warm_run_of(size_t texel, int width) {
  return int(texel / size_t(width)) / kWarmRunRows;
}
// Where the warm-start runs of `count` fragments in texel order begin, with `count` appended;
// texel_of(i) is the i-th fragment's texel. Eval and sweep cut their runs with this.
template <class TexelOf>
std::vector<size_t> warm_run_begins(size_t count, int width, TexelOf texel_of) {
  std::vector<size_t> begins;
  for (size_t i = 0; i < count; ++i)
    if (i == 0 || warm_run_of(texel_of(i), width) != warm_run_of(texel_of(i - 1), width))
      begins.push_back(i);
  begins.push_back(count);
  return begins;
}

// "fast" (our exact dense simplex) or "glpk" (the reference).
std::unique_ptr<Backend> make_backend(const std::string& name);
// InputError naming `what` when a basis of `functions` is beyond backend `name`'s row limit.
void check_backend_rows(const std::string& name, int functions, const std::string& what);
std::vector<std::string> backend_names();

}  // namespace mb::lp
