#include "eval/lp_view_solver.h"

#include <omp.h>

#include <algorithm>
#include <memory>

#include "continuous/discretized.h"
#include "eval/warm_runs.h"
#include "lp/solution.h"
#include "techniques/lp_fragment_solver.h"
#include "util/parallel_errors.h"

namespace mb {

std::vector<uint32_t> fragments_needing_lp(const Fragments& fragments, double lp_beta) {
  std::vector<uint32_t> list;
  for (size_t k = 0; k < fragments.size(); ++k)
    if (needs_lp(fragments.oracle[k], lp_beta)) list.push_back(uint32_t(k));
  return list;
}

namespace {

// Transformed columns and (quantized) depths per texel, indexed by texel, the far plane's one past
// the map.
struct ViewColumns {
  std::unique_ptr<double[]> depth, columns;
};

// A translucent map's columns (docs/reference.md §7): one per atom, every atom of the map, and the
// far plane's one past the last.
ViewColumns atom_columns(const ShadowMap& map, const Basis& basis,
                         const lp::ProblemFactory& factory, const EvalSettings& settings) {
  const lp::Discretization& disc = settings.technique.lp;
  const int k = factory.rows(), m = int(basis.size());
  const size_t count = map.atom_count() + 1;
  ViewColumns out;
  out.depth.reset(new double[count]);
  std::vector<double> depth(count), values(count);
  for (size_t a = 0; a < count; ++a) {
    const double z = a < map.atom_count() ? map.atom_depth[a] : 1.0;
    depth[a] = out.depth[a] = disc.quantize ? lp::quantize_to_grid(disc, z) : z;
  }
  std::unique_ptr<double[]> raw(new double[count * k]);
  out.columns.reset(new double[count * k]);
  for (size_t a = 0; a < count; ++a) raw[a * k] = 1;
  for (int j = 0; j < m; ++j) {
    basis[j].evaluate(depth, values);
    for (size_t a = 0; a < count; ++a) raw[a * k + j + 1] = values[a];
  }
#pragma omp parallel for schedule(static) num_threads(settings.threads)
  for (size_t a = 0; a < count; ++a) factory.transform(&raw[a * k], &out.columns[a * k]);
  return out;
}

ViewColumns reached_columns(const ViewData& view, const std::vector<uint32_t>& list,
                            const std::vector<size_t>& run_begin, const Basis& basis,
                            const lp::ProblemFactory& factory, const EvalSettings& settings) {
  // Transformed columns T (1, b(z)) of the layer-0 depths the fragments' kernels reach: each
  // run's bounding box grown by the kernel's radius (every texel of a full evaluation, a few
  // blocks of a screen's sample), and the far plane's. Columns no kernel reaches are never read,
  // nor written: the buffers stay uninitialised.
  const ShadowMap& map = view.map;
  const lp::Discretization& disc = settings.technique.lp;
  const int k = factory.rows(), m = int(basis.size());
  const int reach = settings.kernel.radius();
  std::vector<char> reached(map.depth.size(), 0);
  for (size_t run = 0; run + 1 < run_begin.size(); ++run) {
    int x0 = map.width, x1 = -1, y0 = map.height, y1 = -1;
    for (size_t i = run_begin[run]; i < run_begin[run + 1]; ++i) {
      const size_t t = view.fragments.texel[list[i]];
      const int x = int(t % map.width), y = int(t / map.width);
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    x0 = std::max(0, x0 - reach), x1 = std::min(map.width - 1, x1 + reach);
    for (int y = std::max(0, y0 - reach); y <= std::min(map.height - 1, y1 + reach); ++y)
      std::fill_n(reached.begin() + long(size_t(y) * map.width + x0), x1 - x0 + 1, char(1));
  }
  std::vector<size_t> needed;  // texel indices, ascending, the far plane's (map size) last
  for (size_t t = 0; t < reached.size(); ++t)
    if (reached[t]) needed.push_back(t);
  needed.push_back(map.depth.size());
  const size_t texels = map.depth.size() + 1;  // outside: index = map size
  ViewColumns out;
  out.depth.reset(new double[texels]);
  double* depth = out.depth.get();
  std::vector<double> picked(needed.size()), values(needed.size());
  for (size_t n = 0; n < needed.size(); ++n) {
    const double z = needed[n] < map.depth.size() ? map.depth[needed[n]] : 1.0;
    picked[n] = depth[needed[n]] = disc.quantize ? lp::quantize_to_grid(disc, z) : z;
  }
  std::unique_ptr<double[]> raw(new double[needed.size() * k]);
  out.columns.reset(new double[texels * k]);
  double* columns = out.columns.get();
  for (size_t n = 0; n < needed.size(); ++n) raw[n * k] = 1;
  for (int j = 0; j < m; ++j) {
    basis[j].evaluate(picked, values);
    for (size_t n = 0; n < needed.size(); ++n) raw[n * k + j + 1] = values[n];
  }
#pragma omp parallel for schedule(static) num_threads(settings.threads)
  for (size_t n = 0; n < needed.size(); ++n)
    factory.transform(&raw[n * k], &columns[needed[n] * k]);
  return out;
}

// One thread's state for its runs of fragments: the LP fragment solver, the problem that move_zf
// updates between the fragments of one texel, and the kernel's taps (no allocation per LP).
class RunSolver {
 public:
  RunSolver(const ViewData& view, const ViewColumns& reached, const lp::ProblemFactory& factory,
            const Basis& basis, const EvalSettings& settings, const KernelAtomMap& atoms)
      : view_(view),
        reached_(reached),
        factory_(factory),
        settings_(settings),
        atoms_(atoms),
        solver_(basis, factory, settings.technique),
        taps_(settings.kernel.size * settings.kernel.size),
        tap_depth_(taps_),
        tap_weight_(taps_),
        tap_column_(taps_),
        tap_texel_(taps_) {}

  // Fragment f, cold when it starts its run (so answers do not depend on the schedule);
  // `same_kernel` when the previous fragment of the run sat on the same texel.
  // A translucent kernel's atoms are not its taps, which the warm starts' atom map assumes
  // (eval/warm_runs.h): every fragment starts cold.
  const lp::Solution& solve(size_t f, bool cold, bool same_kernel) {
    cold = cold || view_.map.translucent();
    const size_t t = view_.fragments.texel[f];
    const int x = int(t % view_.map.width), y = int(t / view_.map.width);
    const double zf = view_.fragments.ztest[f];  // z_f - delta_f (docs/reference.md §3)
    if (!same_kernel) gather_taps(x, y);
    // lp.moment_box: the box around the kernel's stored moments needs no problem columns.
    if (solver_.reads_problem() && (!same_kernel || !factory_.move_zf(zf, problem_)))
      factory_.from_distribution(tap_depth_, tap_weight_, tap_column_, zf, problem_);
    const lp::WarmStart at = warm_start_at(view_.fragments.layer[f], x, y, &atoms_);
    return solver_.solve(problem_, tap_depth_, tap_weight_, zf, cold ? nullptr : &at);
  }

 private:
  // The kernel's taps in kernel_distribution's order; the extra texel index picks the column (the
  // far plane's, one past the map, for taps outside it).
  void gather_taps(int x, int y) {
    if (view_.map.translucent()) {
      kernel_atoms(view_.map, settings_.kernel, x, y, tap_depth_, tap_weight_, &tap_texel_);
      tap_column_.resize(tap_depth_.size());
    } else {
      kernel_distribution(view_.map, settings_.kernel, x, y, tap_depth_, tap_weight_, tap_texel_);
    }
    const int k = factory_.rows();
    for (size_t n = 0; n < tap_depth_.size(); ++n) {
      tap_depth_[n] = reached_.depth[tap_texel_[n]];  // quantized in quantize mode
      tap_column_[n] = &reached_.columns[tap_texel_[n] * k];
    }
  }

  const ViewData& view_;
  const ViewColumns& reached_;
  const lp::ProblemFactory& factory_;
  const EvalSettings& settings_;
  const KernelAtomMap& atoms_;
  LpFragmentSolver solver_;
  lp::Problem problem_;
  int taps_;
  std::vector<double> tap_depth_, tap_weight_;
  std::vector<const double*> tap_column_;
  std::vector<size_t> tap_texel_;
};

}  // namespace

LpViewAnswers solve_lp_view(const ViewData& view, const std::vector<uint32_t>& list,
                            const Basis& basis, const lp::ProblemFactory& factory,
                            const EvalSettings& settings, ProgressBar* progress,
                            const std::vector<size_t>* runs_given) {
  uint64_t solved = 0, infeasible = 0, unstable = 0;
  // Warm-start runs (bands of kWarmRunRows texel rows; fragments are in texel order): each
  // run is solved in order by one thread, first from scratch, so the answers do not depend on
  // the schedule.
  const std::vector<size_t> run_begin =
      runs_given ? *runs_given : warm_run_begins(list.size(), view.map.width, [&](size_t i) {
        return view.fragments.texel[list[i]];
      });
  const ViewColumns reached =
      view.map.translucent() ? atom_columns(view.map, basis, factory, settings)
                             : reached_columns(view, list, run_begin, basis, factory, settings);
  const size_t runs = run_begin.size() - 1;
  const KernelAtomMap atoms(settings.kernel.size);
  std::vector<double> g(view.fragments.size(), 0.0);  // skipped fragments: G = 0 exactly
  ParallelErrors errors;  // each run captured: a throw must not leave the worksharing loop
#pragma omp parallel num_threads(settings.threads) reduction(+ : solved, infeasible, unstable)
  {
    RunSolver solver(view, reached, factory, basis, settings, atoms);
#pragma omp for schedule(dynamic, 1)
    for (size_t run = 0; run < runs; ++run)
      errors.capture([&] {
        for (size_t i = run_begin[run]; i < run_begin[run + 1]; ++i) {
          const size_t f = list[i];
          // The fragments of one texel share its kernel (41 % of them follow one of their
          // texel's): then only z_f's column changes, and the problem is the same as built anew.
          const bool same_kernel =
              i > run_begin[run] && view.fragments.texel[list[i - 1]] == view.fragments.texel[f];
          const lp::Solution& s = solver.solve(f, i == run_begin[run], same_kernel);
          if (s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal) {
            g[f] = std::clamp(s.G, 0.0, 1.0);
            ++solved;
          } else if (s.status == lp::ProblemStatus::Infeasible) {
            ++infeasible;  // shown lit (G = 0), counted
          } else {
            ++unstable;
          }
        }
        if (progress) progress->advance(run_begin[run + 1] - run_begin[run]);
      });
  }
  errors.rethrow();
  return {std::move(g), solved, infeasible, unstable};
}

}  // namespace mb
