#pragma once
// A backend that hands the LPs its primary cannot answer (unstable, iteration limit) to GLPK, and
// accepts GLPK's answer only with an independent certificate (lp/kkt_checker.h): "fast" is our
// simplex wrapped in this. Solution::engine names which solver answered, so comparisons of the
// two backends can leave GLPK's own answers out.
#include <memory>

#include "lp/solution.h"

namespace mb::lp {

std::unique_ptr<Backend> make_fallback_backend(std::unique_ptr<Backend> primary);

}  // namespace mb::lp
