#pragma once
// Lane kernels: the fast simplex's loops over columns, rows or basis positions, each with a scalar
// reference (lanes_scalar.h, compiled in every build) and SIMD paths (lanes_avx2.h,
// lanes_avx512.h) that must return the reference's bits exactly. This header picks the widest path
// the build's instruction set has; tests/lp_lanes_test.cpp compares every path the build has with
// the reference, so the answers do not depend on the instruction set (docs/reference.md §2 promises
// G to 1e-9; the project promises more: the same bits on every thread count and path).
#include "lp/lanes/lanes_avx2.h"
#include "lp/lanes/lanes_avx512.h"
#include "lp/lanes/lanes_scalar.h"

namespace mb::lp::fast::lanes {

#if defined(__AVX512F__)
constexpr const char* kPath = "avx512";
using avx512::any_below;
using avx512::basic_points;
using avx512::bracket_extras;
using avx512::closest;
using avx512::combine;
using avx512::copy_row;
using avx512::first_holding;
using avx512::first_sign_change;
using avx512::for_each_below;
using avx512::front_costs;
using avx512::greatest_decrease;
using avx512::misfit;
using avx512::nearest_beyond;
using avx512::nearest_beyond_each;
using avx512::nearest_other;
using avx512::offer_distances;
using avx512::same_row;
using avx512::smallest_of;
using avx512::update_inverse;
#elif defined(__AVX2__) && defined(__FMA__)
constexpr const char* kPath = "avx2";
using avx2::combine;
using avx2::first_holding;
using avx2::for_each_below;
using avx2::nearest_beyond_each;
using avx2::smallest_of;
using scalar::any_below;
using scalar::basic_points;
using scalar::bracket_extras;
using scalar::closest;
using scalar::copy_row;
using scalar::first_sign_change;
using scalar::front_costs;
using scalar::greatest_decrease;
using scalar::misfit;
using scalar::nearest_beyond;
using scalar::nearest_other;
using scalar::offer_distances;
using scalar::same_row;
using scalar::update_inverse;
#else
constexpr const char* kPath = "scalar";
using namespace scalar;
#endif

}  // namespace mb::lp::fast::lanes
