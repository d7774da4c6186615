#pragma once
// The answer of an LP backend: a *call* status (did the solver run) kept apart from the
// *problem* status (what the LP is), as in HiGHS (docs/design.md §Types).
#include <memory>
#include <string>
#include <vector>

#include "lp/problem.h"

namespace mb::lp {

// Unstable: numerical trouble (no basis could be certified); IterationLimit: the simplex stopped at
// its iteration limit (a stalling, ill-conditioned LP). Neither is an answer.
enum class ProblemStatus { Optimal, Infeasible, IterationLimit, Unstable };
// Every Optimal answer's G is within this of the LP's optimum (docs/reference.md §2): the fast
// backend proves it with a certificate, and accepts a GLPK answer only with the KKT checker's.
constexpr double kCertifiedError = 1e-9;
// The finite set the continuous exchange method starts from (docs/reference.md §2): a uniform grid
// of this many points on the interval, with the kernel's depths. Fine enough that the first
// separation steps find the extremal atoms' neighbourhoods, small enough to cost little per LP.
constexpr int kContinuousSeedGrid = 64;
enum class CallStatus { Ok, Failed };
const char* to_string(ProblemStatus status);

// Which solver produced an answer: the fast backend hands the rare LP its simplex cannot certify
// to GLPK (accepted only with an independent certificate), so a comparison of the two backends
// must know which answers are GLPK's own.
enum class Engine { Fast, Glpk, Exact };
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

// Warm starts (Backend::solve_next): problems solved one after another that resemble each other
// (the caller's neighbours) start from each other's optimal bases. The caller says where a basis
// is remembered and which remembered ones to offer; the LP knows nothing of where its problems
// come from.
constexpr int kWarmLanes = 8;

// An opaque position of a problem, given back to the AtomMap (-1: unknown).
struct Place {
  int x = -1, y = -1;
};

// Maps the atoms of a known distribution (Problem::atom_extra's order) between two problems, so
// that a remembered basis's atom columns come back as the atoms that stand for the same depths.
class AtomMap {
 public:
  virtual ~AtomMap() = default;
  // For a basis remembered at `then` and offered to the problem at `now`: table[a] is the atom of
  // `now` that stands for atom a of `then`, for a < size(); null when every atom maps to itself.
  virtual const int* table(Place then, Place now) const = 0;
  virtual int size() const = 0;
};

struct WarmStart {
  // The lane (0..kWarmLanes-1) whose last basis is offered first and in which this problem's
  // optimal basis is remembered (e.g. the fragment's layer, so that lane l continues layer l).
  int lane = 0;
  // Also remember the basis in memory `memory` (>= 0), under its lane; -1: no.
  int memory = -1;
  // Offer every lane's basis of these memories too (-1: none).
  int offers[2] = {-1, -1};
  Place place;                     // stored with the basis, passed to `atoms`
  const AtomMap* atoms = nullptr;  // null: atoms keep their index
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // The most basis functions (rows - 1) this backend solves; callers check it before any work.
  virtual int max_functions() const = 0;
  virtual Solution solve(const Problem& problem) = 0;
  // The same answer to within the certified 1e-9, possibly faster: `problem` continues a run of
  // similar problems, and the backend may start from the optimal bases remembered in `at`'s lanes
  // and memories (WarmStart). The result then depends on the run, so callers that promise results
  // independent of the thread count must cut runs the same way on every schedule and start each
  // with `solve`, which forgets every basis. Backends without warm starts solve from scratch.
  virtual Solution solve_next(const Problem& problem, const WarmStart& at) {
    (void)at;
    return solve(problem);
  }
  // solve (at == nullptr) or solve_next, into `out`, whose storage a backend may reuse: the loops
  // over millions of LPs (sweep, eval's lp:) then allocate nothing per LP (three allocations and
  // frees an LP otherwise).
  virtual void solve_into(const Problem& problem, const WarmStart* at, Solution& out) {
    out = at ? solve_next(problem, *at) : solve(problem);
  }
};

// A backend that implements solve_into only (the loops' entry point); solve and solve_next call it.
class IntoBackend : public Backend {
 public:
  Solution solve(const Problem& problem) override {
    Solution s;
    solve_into(problem, nullptr, s);
    return s;
  }
  Solution solve_next(const Problem& problem, const WarmStart& at) override {
    Solution s;
    solve_into(problem, &at, s);
    return s;
  }
  void solve_into(const Problem& problem, const WarmStart* at, Solution& out) override = 0;
};

// "fast" (our exact dense simplex) or "glpk" (the reference).
std::unique_ptr<Backend> make_backend(const std::string& name);
// InputError naming `what` when a basis of `functions` is beyond backend `name`'s row limit.
void check_backend_rows(const std::string& name, int functions, const std::string& what);
// Every name make_backend takes: the one list option tables and errors print.
std::vector<std::string> backend_names();

}  // namespace mb::lp
