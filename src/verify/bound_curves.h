#pragma once
// The seed paper's Figure 3 (docs/reference.md §1-2): for one depth distribution, the true CDF
// F_Z(z_f) and the sharp lower bounds G(b, z_f) of Problem 1 as functions of z_f, for the first m
// functions of each given basis (m = 2, 3, 4 by default), solved as LPs.
#include <string>
#include <vector>

#include "basis/basis.h"
#include "lp/problem.h"
#include "scene/dataset.h"
#include "shadow/gaussian_kernel.h"

namespace mb {

struct BoundCurveRequest {
  std::vector<double> depths, weights;  // the kernel's distribution (weights are normalised)
  std::vector<std::string> bases;       // each a named set or "f1; f2; ..." (lp: technique syntax)
  std::vector<int> sizes = {2, 3, 4};   // m: the first m functions of each basis
  int samples = 401;                    // z_f values, uniform on [zf_lo, zf_hi]
  double zf_lo = 0, zf_hi = 1;
  lp::Discretization lp;  // I = grid ∪ the distribution's depths ∪ {z_f}
  std::string backend = "fast";
  int threads = 1;
};

struct BoundSeries {
  std::string basis;                   // as requested
  std::vector<std::string> functions;  // the m functions used
  int m = 0;
  std::vector<double> lower;  // G per z_f sample; NaN where the LP was not solved to optimality
  size_t failures = 0;
  double mean_gap = 0, max_gap = 0;  // F_Z - G over the solved samples
};

struct BoundCurves {
  std::vector<double> zf, cdf;  // F_Z(z_f) = mass strictly below z_f
  std::vector<BoundSeries> series;
};

// InputError on an empty or invalid distribution, an m larger than a basis, a dependent prefix.
// Deterministic for any thread count (every sample is its own LP).
BoundCurves compute_bound_curves(const BoundCurveRequest& request);

// The kernel's distribution at texel [x, y] of `view` ('scene/view', or 'view' when only one
// scene has it) of `dataset` rendered at `resolution`, into request.depths and weights: the same
// taps as PCF and the moment maps see. Returns where it came from, for the report. InputError
// naming bounds.view or bounds.texel for an unknown or ambiguous view or a texel outside it.
std::string take_texel_distribution(const DatasetDesc& dataset, int resolution,
                                    const std::string& view, const std::vector<int64_t>& texel,
                                    const GaussianKernel& kernel, bool quiet,
                                    BoundCurveRequest& request);

}  // namespace mb
