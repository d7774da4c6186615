#pragma once
// Hausdorff moment shadow mapping (docs/reference.md §4): Problem 1 for I = [0, 1] and the power
// basis.
#include "moments/hamburger.h"

namespace mb {

// b = (b1, b2, b3, b4), already biased.
MsmBound<double> hausdorff4(const double* b, double zf);

}  // namespace mb
