#include "verify/bound_curves.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "continuous/discretized.h"
#include "eval/evaluation.h"
#include "lp/solution.h"
#include "techniques/lp_technique.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel_errors.h"

namespace mb {

namespace {

// Validates the request; returns the distribution's total weight.
double checked_total_weight(const BoundCurveRequest& r) {
  if (r.depths.empty()) throw InputError("bounds.depths: expected at least one depth");
  if (r.depths.size() != r.weights.size())
    throw InputError("bounds.weights: expected one weight per depth (" +
                     std::to_string(r.depths.size()) + "), got " +
                     std::to_string(r.weights.size()));
  double total = 0;
  for (size_t t = 0; t < r.depths.size(); ++t) {
    if (!std::isfinite(r.depths[t]))
      throw InputError("bounds.depths: depth " + std::to_string(t + 1) + " is " +
                       round_trip(r.depths[t]) + ", expected a finite number");
    if (!(r.weights[t] >= 0) || !std::isfinite(r.weights[t]))
      throw InputError("bounds.weights: weight " + std::to_string(t + 1) + " is " +
                       round_trip(r.weights[t]) + ", expected a finite number >= 0");
    if (r.depths[t] < r.lp.lo || r.depths[t] > r.lp.hi)
      throw InputError("bounds.depths: depth " + round_trip(r.depths[t]) +
                       " lies outside the LP interval [" + round_trip(r.lp.lo) + ", " +
                       round_trip(r.lp.hi) + "] (lp.lo, lp.hi); expected a depth inside it");
    total += r.weights[t];
  }
  if (!(total > 0))
    throw InputError("bounds.weights: expected a positive total weight, got " + round_trip(total));
  if (r.samples < 2)
    throw InputError("bounds.samples: expected at least 2 z_f values, got " +
                     std::to_string(r.samples));
  if (!(r.zf_lo < r.zf_hi))
    throw InputError("bounds.zf_range: expected lo < hi, got [" + round_trip(r.zf_lo) + ", " +
                     round_trip(r.zf_hi) + "]");
  return total;
}

}  // namespace

BoundCurves compute_bound_curves(const BoundCurveRequest& r) {
  const double total = checked_total_weight(r);
  BoundCurves out;
  for (int i = 0; i < r.samples; ++i) {
    const double zf = r.zf_lo + (r.zf_hi - r.zf_lo) * i / (r.samples - 1);
    double cdf = 0;  // docs/reference.md §1: strictly less
    for (size_t t = 0; t < r.depths.size(); ++t)
      if (r.depths[t] < zf) cdf += r.weights[t] / total;
    out.zf.push_back(zf);
    out.cdf.push_back(cdf);
  }
  for (const auto& spec : r.bases) {
    const std::vector<std::string> items = lp_technique_basis(lp_technique_name(spec));
    const Basis full = Basis::parse(items);
    for (int m : r.sizes) {
      if (m < 1 || size_t(m) > full.size())
        throw InputError("bounds.sizes: m = " + std::to_string(m) + " needs " + std::to_string(m) +
                         " functions, but basis '" + spec + "' has " + std::to_string(full.size()));
      std::vector<BasisFunction> prefix;
      for (int j = 0; j < m; ++j) prefix.push_back(full[j]);
      Basis basis(prefix);
      basis.check_independent(r.lp.lo, r.lp.hi);
      const lp::ProblemFactory factory(basis, r.lp);
      BoundSeries series;
      series.basis = spec;
      series.functions = basis.names();
      series.m = m;
      series.lower.assign(out.zf.size(), std::numeric_limits<double>::quiet_NaN());
      size_t failures = 0;
      ParallelErrors errors;
#pragma omp parallel num_threads(r.threads) reduction(+ : failures)
      {
        auto backend = lp::make_backend(r.backend);
#pragma omp for schedule(dynamic, 4)
        for (size_t i = 0; i < out.zf.size(); ++i)
          errors.capture([&] {
            // The distribution's depths join I and fix the moments: feasible by construction (§2).
            lp::Problem problem = factory.from_distribution(r.depths, r.weights, out.zf[i]);
            const lp::Solution s =
                lp::solve_discretized(factory, problem, *backend, r.depths, r.weights).finite;
            if (s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal)
              series.lower[i] = std::clamp(s.G, 0.0, 1.0);
            else
              ++failures;
          });
      }
      errors.rethrow();
      series.failures = failures;
      size_t solved = 0;
      double gap_sum = 0;
      for (size_t i = 0; i < out.zf.size(); ++i) {
        if (std::isnan(series.lower[i])) continue;
        const double gap = out.cdf[i] - series.lower[i];
        gap_sum += gap;
        series.max_gap = std::max(series.max_gap, gap);
        ++solved;
      }
      series.mean_gap =
          solved ? gap_sum / double(solved) : std::numeric_limits<double>::quiet_NaN();
      out.series.push_back(std::move(series));
    }
  }
  return out;
}

std::string take_texel_distribution(const DatasetDesc& dataset, int resolution,
                                    const std::string& wanted, const std::vector<int64_t>& texel,
                                    const GaussianKernel& kernel, bool quiet,
                                    BoundCurveRequest& request) {
  if (texel.size() != 2) throw InputError("bounds.texel: expected two integers [x, y]");
  EvalSettings settings;
  settings.kernel = kernel;
  settings.threads = request.threads;
  const auto views = prepare_views(dataset, resolution, settings, quiet);
  std::string names, matches;
  const ViewData* found = nullptr;
  for (const auto& v : views) {
    const std::string full = v.scene + "/" + v.view;
    names += (names.empty() ? "" : ", ") + full;
    if (wanted != full && wanted != v.view) continue;
    matches += (matches.empty() ? "" : ", ") + full;
    if (found)
      throw InputError("bounds.view: '" + wanted + "' names several views (" + matches +
                       "); write scene/view");
    found = &v;
  }
  if (!found)
    throw InputError("bounds.view: no view '" + wanted + "' in dataset " + dataset.name +
                     "; views: " + names);
  const ViewData& v = *found;
  const int x = int(texel[0]), y = int(texel[1]);
  if (x >= v.map.width || y >= v.map.height)
    throw InputError("bounds.texel: (" + std::to_string(x) + ", " + std::to_string(y) +
                     ") lies outside view " + v.scene + "/" + v.view + " (" +
                     std::to_string(v.map.width) + "x" + std::to_string(v.map.height) + ")");
  kernel_atoms(v.map, kernel, x, y, request.depths, request.weights);
  return "dataset " + dataset.name + ", view " + v.scene + "/" + v.view + ", texel (" +
         std::to_string(x) + ", " + std::to_string(y) + "), " + std::to_string(kernel.size) + "x" +
         std::to_string(kernel.size) + " Gaussian kernel";
}

}  // namespace mb
