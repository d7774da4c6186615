#pragma once
// Six power moments judged over their double rounding box (docs/reference.md §6, "Six moments in
// double"). A closed form reads b~, the kernel's moments b rounded to double; for a narrow kernel
// the 4x4 Hankel matrix is so ill-conditioned that Problem 1 at b~ and at b differ by far more
// than any tolerance (0.008 against 3e-7 on one real receiver), although both lie in the box
// |b' - b~| <= a few ulps. What an exact-in-double closed form owes is Problem 1 at b~, and that
// is bracketed without trusting any closed form:
// - below by the exact moments' certificate phi (phi - delta (1 + u^6) <= step + violation on R,
//   proven by the continuous LP; delta > 0 where a far tail needed it):
//   G(b~) >= E_b~[phi] - delta (1 + E_b~[u^6]) - violation, evaluated in 50 digits (weak duality,
//   for every b~ in the moment cone);
// - above by a witness: a distribution whose moments are b~ to 50 digits (its Hankel matrix
//   positive definite, the canonical representation through z_f with real nodes and weights
//   >= 0, checked to reproduce all seven moments), whose mass below z_f is >= G(b~) and whose
//   mass at or below z_f is <= G+(b~) (docs/reference.md §7).
// Where b~ is no distribution's moments (outside the moment cone), Problem 1 at b~ has no value
// and there is nothing to judge.
#include <span>
#include <vector>

#include "lp/solution.h"
#include "verify/verification.h"

namespace mb {

struct RoundedMomentBracket {
  bool inside = false;  // b~ has a witness (the bracket's upper end exists)
  double lower = 0;     // E_b~[phi] - delta (1 + E_b~[u^6]) - violation <= G(b~)
  double upper = 1;     // the witness's mass below z_f >= G(b~)
  double upper_at = 1;  // the witness's mass at or below z_f <= G+(b~)
};

// read = (b~_1, .., b~_6); the certificate phi(u) = sum_k coefficients[k] u^k in the local
// coordinate u = (z - mean) / scale (continuous/local_power.h) with its tail term delta and
// violation: phi - delta (1 + u^6) - step <= violation on R (continuous/continuous.h).
RoundedMomentBracket six_moment_bracket(std::span<const double> read, double zf,
                                        std::span<const long double> coefficients,
                                        long double delta, double violation, double mean,
                                        double scale);

// VerifyTarget::rounding_box rows: the closed form's G + w_1 on the moments it read (b~) into
// `c.closed_upper`, and the bracket [upper_floor, lp_upper] of G+ at b~ from the mirrored
// problem's certificate and witness, with its rounding allowance `c.upper_rounding`. Needs
// `c.upper_floor` from the continuous LP's witness (solve_continuous); leaves `c` as it is where
// b~ has no witness or the mirrored LP is not proven.
void solve_upper_box(const VerifyInstance& inst, VerifyCase& c, lp::Backend& backend);

}  // namespace mb
