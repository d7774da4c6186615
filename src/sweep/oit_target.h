#pragma once
// The transparency sweep target (docs/transparency.md §7): a candidate is `lp:<its functions>` on
// the warped depth, by default (lp.beta = 0) the LP's sharp lower bound of the absorbance in front
// of each transparent fragment, and its error is the opacity-weighted |T_ref - T| of `oit` over
// every camera frame of the dataset. In ErrorStats' terms the reference is 1 - T_ref and the answer
// 1 - T, so "leak" is transmittance too high and "over-darkening" too low, which the exact LP
// of the exact moments never does (the LP of the moments rounded to double may, where fragments
// lie close: candidate_darkening_reason). Pixels with one transparent fragment need no LP: nothing
// lies in front of it, T = T_ref = 1 for every candidate.
#include <memory>
#include <vector>

#include "oit/oit_run.h"
#include "sweep/sweep_target.h"

namespace mb {

// Keeps a reference to `frames`; `params.lp` are the candidates' LP settings (with lp.beta > 0 the
// blend towards the LP's maximum) and `params.beta` the reference MBOIT rows' overestimation.
std::unique_ptr<SweepTarget> make_oit_target(const std::vector<SceneFrame>& frames,
                                             const OitParams& params, int threads);

}  // namespace mb
