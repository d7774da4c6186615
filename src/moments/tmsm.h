#pragma once
// Trigonometric moment shadow mapping (docs/reference.md §4 "TMSM"): the sharp lower bound of
// Problem 1 for I = [0, 1] and the basis (sin 2πz, cos 2πz, sin 4πz, cos 4πz), in closed form
// (one quartic). The derivation is in tmsm.md beside this file.
#include "moments/hamburger.h"

namespace mb {

// b = (E sin 2πz, E cos 2πz, E sin 4πz, E cos 4πz), already biased. Real = float or double.
// nodes/weights: the extremal distribution in depth (the cut reported as depth 1, where it
// does not shadow); at_zf: its weight at z_f. Without with_support only lower and at_zf are set.
template <class Real>
MsmBound<Real> tmsm(const Real* b, Real zf, bool with_support = true);

// The bias of tmsm.md §6: towards the uniform distribution, whose trigonometric moments are 0.
template <class Real>
void bias_trigonometric_moments(Real* b, Real alpha) {
  for (int j = 0; j < 4; ++j) b[j] *= 1 - alpha;
}

}  // namespace mb
