#pragma once
// What closed-form solvers share: the darkening bound of a moment bias, and what happens to an
// answer that is not a number.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "techniques/technique.h"

namespace mb {

// The power-moment solvers share the bias towards b* = (1/2, .., 1/2) (docs/reference.md §4: the
// moments of half the mass at 0 and half at 1) and the beta blend of seed 004.
// Closed forms share what happens to an answer: a NaN (a singular Hankel or Toeplitz matrix at
// alpha = 0 with a kernel of one or two depths) is counted, reported, and shown as fully lit so it
// cannot hide inside the mean; anything else is clamped to [0, 1].
class ClosedFormTechnique : public Technique {
 public:
  size_t failures() const override { return failures_; }

 protected:
  using Technique::Technique;
  // Moments biased by alpha towards those of a distribution on I are a mixture's; the sharp bound
  // of the mixture lies below (1 - alpha) F_Z + alpha, so G exceeds F_Z by at most alpha. Float and
  // 16-bit storage round the moments off the kernel's moment set, and beta > 0 blends towards the
  // upper bound: neither is a lower bound any more.
  double closed_form_bound(double alpha, double beta) const {
    const bool exact_storage = storage().kind == StorageKind::Double;
    return exact_storage && beta == 0 ? alpha : std::numeric_limits<double>::infinity();
  }
  std::string closed_form_reason(double beta) const {
    if (beta > 0) return "beta > 0 blends the lower bound towards the upper bound (seed 004)";
    return "moments stored in " + storage().name() +
           " are rounded off the kernel's moment set, and the bias alpha does not always pull them "
           "back";
  }
  double finish(double g) {
    if (std::isfinite(g)) return std::clamp(g, 0.0, 1.0);
    ++failures_;
    return 0;
  }

 private:
  size_t failures_ = 0;
};

}  // namespace mb
