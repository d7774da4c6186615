#pragma once
// Our exact backend: a dense revised simplex specialised to m + 1 <= 8 rows (docs/reference.md §2).
// "Exact" means the same optimum as an exact solution to 1e-9 on every instance: every answer is
// re-certified before it is returned, or reported as unstable or at its iteration limit.
// The simplex itself lives in lp/fast/.
#include "lp/fast/settings.h"
#include "lp/row_count.h"
#include "lp/solution.h"

namespace mb::lp {

// Our simplex alone; make_backend("fast") wraps it in the GLPK fallback (lp/fallback_backend.h).
std::unique_ptr<Backend> make_fast_backend(const fast::SimplexSettings& settings = {});

}  // namespace mb::lp
