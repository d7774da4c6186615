#pragma once
// How a moment map is stored on a GPU, emulated (docs/reference.md §4, §8): exact double, float32,
// or k-bit unorm after an affine transform q = A b + c (seed 000's theta_4 for the power moments,
// theta_2 for VSM, or any admissible transform, moments/quantization_transform.h) that spreads the
// moments over [0,1]^m before rounding and is inverted after filtering.
#include <span>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "util/eigen.h"

namespace mb {

enum class StorageKind { Double, Float32, Unorm };

struct MomentStorage {
  StorageKind kind = StorageKind::Double;
  int bits = 0;               // Unorm only: bits a channel (unorm_bit_depths)
  Eigen::MatrixXd transform;  // Unorm only: q = transform * b + offset
  Eigen::VectorXd offset;
  // "double", "float32", "unorm<bits>" (the lp.moment_box value of the same format).
  std::string name() const;
};

// The unorm channel widths a GPU render target offers and a map may use: 8 (RGBA8_UNORM), 10
// (RGB10A2_UNORM's colour channels) and 16 (RGBA16_UNORM) (docs/reference.md §8).
const std::vector<int>& unorm_bit_depths();

MomentStorage double_storage();
MomentStorage float32_storage();
// `bits` a channel after q = transform * b + offset. The transform must be admissible (map the
// basis's curve over [0, 1] into [0, 1]^m, as quantization_transform's are by construction):
// values outside are clamped, which storage_tolerance does not cover. InputError naming `what`
// for a bit depth outside unorm_bit_depths, a non-square or singular transform, or an offset of
// another size.
MomentStorage unorm_storage(int bits, Eigen::MatrixXd transform, Eigen::VectorXd offset,
                            const std::string& what = "storage");
// 16 bits with seed 000's theta_4 (docs/reference.md §4) for b = (z, z^2, z^3, z^4).
MomentStorage unorm16_power4_storage();
// theta_2 for VSM's b = (z, z^2): q = (z, 4z - 4z^2).
MomentStorage unorm16_power2_storage();
// 10 bits with this project's theta_6 for b = (z, .., z^6) (docs/reference.md §8): seed 004 §2.5
// stores six moments at 10 bits a channel with a transform it does not print.
MomentStorage unorm10_power6_storage();

// b -> what the texel holds (rounded), in place.
void store_moments(const MomentStorage& storage, std::span<double> b);
// A stored value -> the nearest the target's format holds (float32 or k-bit unorm), in place.
void round_stored(const MomentStorage& storage, std::span<double> q);
// The blend unit's "over" into a stored target (docs/reference.md §7): dst = alpha * src +
// (1 - alpha) * dst, rounded to the format, as a GPU writes every blend step. Seed 004 §4 blends
// theta_4's values into two RG16 targets; src is the fragment's unrounded stored value.
void blend_stored(const MomentStorage& storage, std::span<double> dst, std::span<const double> src,
                  double alpha);
// Filtered stored values -> moments, in place (inverse transform; identity otherwise).
void load_moments(const MomentStorage& storage, std::span<double> q);

// A distribution's stored values as a map holds them after filtering, before loading: each
// depth's b stored (rounded), then the weighted sum (load_moments turns them into moments).
std::vector<double> filtered_stored_values(const MomentStorage& storage, const Basis& basis,
                                           std::span<const double> depths,
                                           std::span<const double> weights);

// The values the map holds after filtering, before loading: transform * b + offset for unorm,
// the moments themselves otherwise.
std::vector<double> stored_values(const MomentStorage& storage, std::span<const double> moments);

// How far a filtered stored value can lie from the one the exact moments would give, per stored
// value, for depths in [0, 1] (docs/reference.md §2 "Moments with a tolerance", §4): float32 rounds
// each texel's b_j to the nearest float, within 2^-24 |b_j|, so the weighted sum is within
// 2^-24 max over [0, 1] of |b_j|; k-bit unorm rounds each texel's q_i to the nearest of 2^k
// steps, within 0.5 / (2^k - 1) (an admissible transform keeps [0, 1] inside [0, 1]^m, so nothing
// is clamped); a translucent
// texel blended step by step (blend_stored) is off by up to one such rounding per step, which this
// tolerance does not cover: the LP's moment box rounds the kernel's atoms itself. Both plus 8
// double ulps of the value's scale for the filter's own sums and the transform's round trip (for
// unorm, of q's computation: m ulps of sum_i |A_ji| max |b_i|, large for theta_6). The
// largest |b_j| is proven for catalog functions (samples plus half a spacing times the bound of
// b_j'); sampled with a 1 % margin for expressions.
std::vector<double> storage_tolerance(const MomentStorage& storage, const Basis& basis);

}  // namespace mb
