#pragma once
// Eigen, with the compiler's AVX-512 header false positive silenced for third-party lines only
// (util/simd_intrinsics.h says why). Include this, never <Eigen/...> directly.
#include "util/simd_intrinsics.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#pragma GCC diagnostic pop
