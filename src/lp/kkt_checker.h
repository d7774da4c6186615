#pragma once
// An independent check of an LP solution from the solution alone (docs/design.md §Style, after
// HiGHS): primal feasibility, dual feasibility, complementarity and the duality gap, combined into
// a bound on |G - G*| that the tolerance applies to.
#include <string>

#include "lp/solution.h"

namespace mb::lp {

struct KktReport {
  double primal_residual = 0;     // max |A w - rhs|
  double negative_weight = 0;     // max(0, -min w)
  double dual_infeasibility = 0;  // max(0, -min reduced cost) over all points
  double complementarity = 0;     // sum w_j |reduced cost_j| over the support
  double duality_gap = 0;         // |c.w - y.rhs|
  // First-order bound on |G - G*| (docs/reference.md §2 dual): sum_r |y_r| |residual_r| (what the
  // residual can move the optimum by) + dual infeasibility (weak duality with sum w = 1) +
  // complementarity. A residual of 1e-10 is harmless with |y| ~ 1, decisive with |y| ~ 1e8 (nearly
  // dependent bases on the boundary of the moment space).
  double error_bound = 0;
  bool ok = false;
  std::string describe() const;
};

// ok when every quantity above except the error bound is <= tolerance (they are O(1)-scaled:
// weights sum to one, rows are orthonormal) and G equals c.w to tolerance. The error bound is
// reported, not judged: with |y| ~ 1e6 it exceeds 1e-9 for any solution rounded to double.
// Residuals and reduced costs are computed in long double.
KktReport check_kkt(const Problem& problem, const Solution& solution, double tolerance = 1e-9);

}  // namespace mb::lp
