#pragma once
// The arbiter: QSopt_ex's exact rational simplex (Applegate, Cook, Dash, Espinoza). The LP's data,
// the double-rounded columns, right-hand side and costs, are exact rationals, so it returns the
// exact optimum of the LP as posed (docs/lp-engine.md § The exact arbiter), against which our
// engine, GLPK and GLPK's exact mode are measured. Slow (rational arithmetic) and serialised (the
// library keeps global state): for tests, verify's worst cases and `solve --backend exact`. No
// QSopt_ex or GMP type leaves exact_backend.cpp.
#include "lp/solution.h"

namespace mb::lp {

// Which right-hand side a problem built from a distribution poses (Problem::start_support): that
// distribution's exact image (what the problem means; `lp.backend exact`), or the rounded double
// one our engine and GLPK solve (to check their answers against the LP they were given).
enum class ExactRhs { DistributionImage, AsRounded };
std::unique_ptr<Backend> make_exact_backend(ExactRhs rhs = ExactRhs::DistributionImage);

}  // namespace mb::lp
