#pragma once
// The scattering sweep target (docs/scattering.md §7): a candidate is `pss_lp:<its functions>` at
// beta 0, Problem 1's sharp lower bound on each view ray's shadowed fraction from the rectified
// row's prefix-summed moments of the candidate's basis, and its error is scatter's mean_error
// against `pss_exact` (the row's own visibility, so that the error is the moments' loss alone),
// Σ|I - I_ref| / Σ S_max over every pixel of every light view and camera. In ErrorStats' terms the
// reference is the shadowed fraction 1 - I_ref / S_max, the answer 1 - I / S_max and each pixel
// weighs S_max, so "leak" is too bright and "over-darkening" too dark, which the lower bound never
// is beyond the LP's certified error.
#include <memory>
#include <vector>

#include "scatter/scatter_frames.h"
#include "sweep/sweep_target.h"

namespace mb {

// Keeps a reference to `frames`; `options` are scatter's (the candidates take beta 0 whatever
// scatter.beta says; the reference rows take it as `scatter` does).
std::unique_ptr<SweepTarget> make_scatter_target(const std::vector<ScatterFrame>& frames,
                                                 const ScatterRunOptions& options, int threads);

// The candidate's technique: pss_lp:<f1; f2; ...>.
std::string scatter_candidate_name(const Basis& basis);

}  // namespace mb
