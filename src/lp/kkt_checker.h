#pragma once
// An independent check of an LP solution from the solution alone (DESIGN.md §Style, after HiGHS):
// primal feasibility, dual feasibility, complementarity and the duality gap.
#include <string>

#include "lp/solution.h"

namespace mb::lp {

struct KktReport {
  double primal_residual = 0;     // max |A w - rhs|
  double negative_weight = 0;     // max(0, -min w)
  double dual_infeasibility = 0;  // max(0, -min reduced cost) over all points
  double complementarity = 0;     // max w_j |reduced cost_j| over the support
  double duality_gap = 0;         // |c.w - y.rhs|
  bool ok = false;
  std::string describe() const;
};

// `tolerance` bounds every quantity above (they are all O(1)-scaled: weights sum to one and the
// rows are orthonormal).
KktReport check_kkt(const Problem& problem, const Solution& solution, double tolerance = 1e-9);

}  // namespace mb::lp
