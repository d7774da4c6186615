#pragma once
// How a moment map is stored on a GPU, emulated (REFERENCE.md §4): exact double, float32, or
// 16-bit unorm after an optimised affine transform (theta_4 for the power moments, theta_2 for
// VSM) that spreads the moments over [0,1]^m before rounding and is inverted after filtering.
#include <Eigen/Dense>
#include <span>
#include <string>

namespace mb {

enum class StorageKind { Double, Float32, Unorm16 };

struct MomentStorage {
  StorageKind kind = StorageKind::Double;
  Eigen::MatrixXd transform;  // Unorm16 only: q = transform * b + offset
  Eigen::VectorXd offset;
  std::string name() const;
};

MomentStorage double_storage();
MomentStorage float32_storage();
// theta_4 of REFERENCE.md §4 for b = (z, z^2, z^3, z^4).
MomentStorage unorm16_power4_storage();
// theta_2 for VSM's b = (z, z^2): q = (z, 4z - 4z^2).
MomentStorage unorm16_power2_storage();

// b -> what the texel holds (rounded), in place.
void store_moments(const MomentStorage& storage, std::span<double> b);
// Filtered stored values -> moments, in place (inverse transform; identity otherwise).
void load_moments(const MomentStorage& storage, std::span<double> q);

}  // namespace mb
