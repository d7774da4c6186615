#pragma once
// The arbiter: QSopt_ex's exact rational simplex (Applegate, Cook, Dash, Espinoza). The LP's data,
// the double-rounded columns, right-hand side and costs, are exact rationals, so it returns the
// exact optimum of the LP as posed (docs/lp-engine.md § The exact arbiter), against which our
// engine, GLPK and GLPK's exact mode are measured. Slow (rational arithmetic) and serialised (the
// library keeps global state): for tests, verify's worst cases and `solve --backend exact`. No
// QSopt_ex or GMP type leaves exact_backend.cpp.
#include "lp/solution.h"

namespace mb::lp {

std::unique_ptr<Backend> make_exact_backend();

}  // namespace mb::lp
