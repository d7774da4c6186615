#pragma once
// The reference backend: GLPK's primal simplex. No GLPK type leaves glpk_backend.cpp.
#include "lp/solution.h"

namespace mb::lp {

// Double: GLPK's primal simplex (`lp.backend glpk`). Exact: then GLPK's rational simplex
// (glp_exact) from the basis the double run reached, which results/FINDINGS.md §6b measures
// against the exact arbiter; not a backend of the options (the arbiter is `exact`).
enum class GlpkMode { Double, Exact };
std::unique_ptr<Backend> make_glpk_backend(GlpkMode mode = GlpkMode::Double);

}  // namespace mb::lp
