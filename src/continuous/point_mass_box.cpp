#include "continuous/point_mass_box.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace mb::lp {

namespace {

// Whether the atom at a has its moments in the box (long double, so that a^k keeps the digits the
// tolerances of a few ulps need).
bool atom_in_box(long double a, double lo, double hi, std::span<const double> moments,
                 std::span<const double> tolerance) {
  if (!(a >= lo && a <= hi)) return false;
  long double power = 1;
  for (size_t k = 0; k < moments.size(); ++k) {
    power *= a;
    if (std::abs(power - (long double)moments[k]) > tolerance[k]) return false;
  }
  return true;
}

// Cantelli: a distribution with mean mu and variance at most var has at most
// var / (var + d^2) of its mass at distance d or more on one side of mu.
long double cantelli(long double var, long double d) {
  return d > 0 ? var / (var + d * d) : 1.0L;
}

}  // namespace

std::optional<PointMassBox> point_mass_box(double lo, double hi, std::span<const double> moments,
                                           std::span<const double> tolerance, double zf) {
  if (moments.size() < 2 || tolerance.size() != moments.size()) return std::nullopt;
  const long double m = moments[0], t0 = tolerance[0];
  const long double variance = (long double)moments[1] - m * m;
  // The most variance the box admits beyond the centre's: E[z^2] up by t1, E[z]^2 down by at most
  // 2 |m| t0 + t0^2 (as continuous/local_box.cpp's frame), a few epsilons for the arithmetic.
  const long double floor =
      (tolerance[1] + 2 * std::abs(m) * t0 + t0 * t0) * (1 + 16 * LDBL_EPSILON);
  if (variance > floor) return std::nullopt;
  const long double var_max = std::max(variance, 0.0L) + floor;
  // Atoms across the box of the mean, and z_f itself where it lies in it.
  std::vector<long double> atoms;
  for (int j : {0, -1, 1, -2, 2, -3, 3, -4, 4}) atoms.push_back(m + j * t0 / 4);
  if (std::abs(zf - m) <= t0) atoms.push_back(zf);
  bool below = false, behind = false;  // an atom in the box strictly below z_f; one at or behind
  long double atom_below = 0, atom_behind = 0;
  for (long double a : atoms) {
    if (!atom_in_box(a, lo, hi, moments, tolerance)) continue;
    if (a < zf && !below) below = true, atom_below = a;
    if (a >= zf && !behind) behind = true, atom_behind = a;
  }
  if (!below && !behind) return std::nullopt;
  PointMassBox out;
  // Every distribution in the box has mean in [m - t0, m + t0] and variance at most var_max.
  const long double mu_hi = m + t0, mu_lo = m - t0;
  if (behind) {
    // An atom at or behind z_f has no mass strictly below it: the least G is 0, exactly.
    out.G = 0, out.lower = 0, out.atom = double(atom_behind);
    out.range_lo = 0;
  } else {
    // Every atom lies below z_f: G = 1 there; the least G is at least 1 - Cantelli's mass at or
    // behind z_f.
    out.G = 1, out.atom = double(atom_below);
    out.lower = double(std::clamp(1 - cantelli(var_max, zf - mu_hi), 0.0L, 1.0L));
    out.range_lo = out.lower;
  }
  // The box's largest G: 1 with an atom below z_f, else Cantelli's mass below z_f.
  out.range_hi = below ? 1.0 : double(std::clamp(cantelli(var_max, mu_lo - zf), 0.0L, 1.0L));
  // Rounding the bounds to double: outward.
  out.lower = std::max(0.0, std::nextafter(out.lower, -HUGE_VAL));
  out.range_lo = std::max(0.0, std::nextafter(out.range_lo, -HUGE_VAL));
  if (out.range_hi < 1) out.range_hi = std::min(1.0, std::nextafter(out.range_hi, HUGE_VAL));
  if (out.G == 0) out.lower = out.range_lo = 0;
  return out;
}

}  // namespace mb::lp
