#include "moments/storage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/quantization_transform.h"
#include "util/error.h"

namespace mb {

std::string MomentStorage::name() const {
  switch (kind) {
    case StorageKind::Double:
      return "double";
    case StorageKind::Float32:
      return "float32";
    case StorageKind::Unorm:
      return "unorm" + std::to_string(bits);
  }
  return "?";
}

const std::vector<int>& unorm_bit_depths() {
  static const std::vector<int> depths{8, 10, 16};
  return depths;
}

MomentStorage double_storage() {
  return {};
}
MomentStorage float32_storage() {
  return {StorageKind::Float32, 0, {}, {}};
}

MomentStorage unorm_storage(int bits, Eigen::MatrixXd transform, Eigen::VectorXd offset,
                            const std::string& what) {
  const std::vector<int>& depths = unorm_bit_depths();
  if (std::find(depths.begin(), depths.end(), bits) == depths.end()) {
    std::string valid;
    for (int d : depths) valid += (valid.empty() ? "" : ", ") + std::to_string(d);
    throw InputError(what + ": unorm with " + std::to_string(bits) +
                     " bits a channel; expected one of " + valid +
                     " (the GPU unorm formats, docs/reference.md §8)");
  }
  const Eigen::Index m = transform.rows();
  if (m == 0 || transform.cols() != m || offset.size() != m)
    throw InputError(what +
                     ": the transform must be a square m x m matrix with an offset of m "
                     "values; got " +
                     std::to_string(transform.rows()) + " x " + std::to_string(transform.cols()) +
                     " and " + std::to_string(offset.size()));
  if (!(std::abs(transform.determinant()) > 0))
    throw InputError(what + ": the transform is singular (a stored map could not be read back)");
  return {StorageKind::Unorm, bits, std::move(transform), std::move(offset)};
}

MomentStorage unorm16_power4_storage() {
  Eigen::MatrixXd a(4, 4);
  // docs/reference.md §4 (seed 000, Section 4.3): maps [0,1] into [0,1]^4, gaining ~12.3 bits.
  a << -2.07224649, 32.23703778, -68.571074599, 39.3703274134,      //
      13.7948857237, -59.4683975703, 82.0359750338, -35.364903257,  //
      0.105877704, -1.9077466311, 9.3496555107, -6.6543490743,      //
      9.7924062118, -33.7652110555, 47.9456096605, -23.9728048165;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(4);
  c(0) = 0.035955884801;
  return unorm_storage(16, std::move(a), std::move(c));
}

MomentStorage unorm16_power2_storage() {
  Eigen::MatrixXd a(2, 2);
  a << 1, 0, 4, -4;
  return unorm_storage(16, std::move(a), Eigen::VectorXd::Zero(2));
}

MomentStorage unorm10_power6_storage() {
  QuantizationTransform t = power6_optimized_transform();
  return unorm_storage(10, std::move(t.A), std::move(t.c));
}

void round_stored(const MomentStorage& storage, std::span<double> q) {
  switch (storage.kind) {
    case StorageKind::Double:
      return;
    case StorageKind::Float32:
      for (double& v : q) v = double(float(v));
      return;
    case StorageKind::Unorm: {
      const double steps = std::ldexp(1.0, storage.bits) - 1;  // exact: 65535 for 16 bits
      for (double& v : q) v = std::round(std::clamp(v, 0.0, 1.0) * steps) / steps;
      return;
    }
  }
}

void store_moments(const MomentStorage& storage, std::span<double> b) {
  if (storage.kind == StorageKind::Unorm) {
    Eigen::Map<Eigen::VectorXd> v(b.data(), Eigen::Index(b.size()));
    v = storage.transform * v + storage.offset;
  }
  round_stored(storage, b);
}

void blend_stored(const MomentStorage& storage, std::span<double> dst, std::span<const double> src,
                  double alpha) {
  for (size_t j = 0; j < dst.size(); ++j) dst[j] = alpha * src[j] + (1 - alpha) * dst[j];
  round_stored(storage, dst);
}

void load_moments(const MomentStorage& storage, std::span<double> q) {
  if (storage.kind != StorageKind::Unorm) return;
  Eigen::Map<Eigen::VectorXd> v(q.data(), Eigen::Index(q.size()));
  Eigen::VectorXd b = storage.transform.partialPivLu().solve(v - storage.offset);
  v = b;
}

std::vector<double> filtered_stored_values(const MomentStorage& storage, const Basis& basis,
                                           std::span<const double> depths,
                                           std::span<const double> weights) {
  const size_t m = basis.size();
  std::vector<double> sum(m, 0.0), column(m);
  for (size_t k = 0; k < depths.size(); ++k) {
    for (size_t j = 0; j < m; ++j) column[j] = basis[j](depths[k]);
    store_moments(storage, column);
    for (size_t j = 0; j < m; ++j) sum[j] += weights[k] * column[j];
  }
  return sum;
}

std::vector<double> stored_values(const MomentStorage& storage, std::span<const double> moments) {
  std::vector<double> q(moments.begin(), moments.end());
  if (storage.kind != StorageKind::Unorm) return q;
  Eigen::Map<Eigen::VectorXd> v(q.data(), Eigen::Index(q.size()));
  v = storage.transform * v + storage.offset;
  return q;
}

namespace {

// max over [0, 1] of |f|, from above.
double largest_magnitude(const BasisFunction& f) {
  constexpr int kSamples = 4096;
  double largest = 0;
  for (int i = 0; i <= kSamples; ++i)
    largest = std::max(largest, std::abs(f(double(i) / kSamples)));
  if (!f.has_derivatives()) return 1.01 * largest;
  // Between samples |f| rises by at most half a spacing times max |f'|.
  return largest + double(f.derivative_bound(1, 0, 1)) / (2 * kSamples);
}

}  // namespace

std::vector<double> storage_tolerance(const MomentStorage& storage, const Basis& basis) {
  constexpr double kUlp = std::numeric_limits<double>::epsilon();
  std::vector<double> scale(basis.size());
  for (size_t j = 0; j < basis.size(); ++j) scale[j] = largest_magnitude(basis[j]);
  std::vector<double> eps(basis.size());
  for (size_t j = 0; j < eps.size(); ++j) {
    switch (storage.kind) {
      case StorageKind::Double:
        eps[j] = 8 * kUlp * scale[j];
        break;
      case StorageKind::Float32:
        eps[j] = std::ldexp(scale[j], -24) + 8 * kUlp * scale[j];
        break;
      case StorageKind::Unorm: {
        // Half a step of the stored value, plus the double rounding of q_j = a_j . b + c_j, off by
        // about m ulps of sum_i |A_ji| |b_i| (theta_6's rows sum to thousands: docs/reference.md
        // §8), plus 8 ulps of q in [0, 1].
        double row = 0;
        for (size_t i = 0; i < basis.size(); ++i)
          row += std::abs(storage.transform(Eigen::Index(j), Eigen::Index(i))) * scale[i];
        eps[j] =
            0.5 / (std::ldexp(1.0, storage.bits) - 1) + 8 * kUlp * (1 + double(basis.size()) * row);
        break;
      }
    }
  }
  return eps;
}

}  // namespace mb
