#pragma once
// Our exact backend: a dense revised simplex specialised to m + 1 <= 8 rows (REFERENCE.md §2).
// "Exact" means the same optimum as an exact solution to 1e-9 on every instance: every answer is
// re-certified from a fresh factorisation before it is returned, or reported as unstable.
#include "lp/solution.h"

namespace mb::lp {

constexpr int kMaxRows = 8;
std::unique_ptr<Backend> make_fast_backend();

}  // namespace mb::lp
