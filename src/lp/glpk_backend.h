#pragma once
// The reference backend: GLPK's primal simplex. No GLPK type leaves glpk_backend.cpp.
#include "lp/solution.h"

namespace mb::lp {

std::unique_ptr<Backend> make_glpk_backend();

}  // namespace mb::lp
