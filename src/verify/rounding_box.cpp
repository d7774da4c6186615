#include "verify/rounding_box.h"

#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>

#include "continuous/local_power.h"
#include "moments/canonical.h"
#include "moments/hamburger.h"

namespace mb {

namespace {
using HP = boost::multiprecision::cpp_bin_float_50;
}  // namespace

RoundedMomentBracket six_moment_bracket(std::span<const double> read, double zf,
                                        std::span<const long double> coefficients,
                                        long double delta, double violation, double mean,
                                        double scale) {
  RoundedMomentBracket out;
  // The read moments in local coordinates, exactly (to 50 digits): l_k = E[((z - mean) / s)^k].
  HP m[7] = {1, read[0], read[1], read[2], read[3], read[4], read[5]};
  HP local[7];
  const HP c = mean, s = scale;
  for (int k = 0; k <= 6; ++k) {
    HP sum = 0, binomial = 1;
    for (int j = 0; j <= k; ++j) {
      sum += binomial * pow(-c, k - j) * m[j];
      binomial = binomial * (k - j) / (j + 1);
    }
    local[k] = sum / pow(s, k);
  }
  HP lower = 0;
  for (size_t k = 0; k < coefficients.size() && k <= 6; ++k)
    lower += HP(coefficients[k]) * local[k];
  // Without the tail term the bound is phi's alone, which a far tail may lift above the step: a
  // canonical node at u ~ -107 with weight 8.6e-11 made it 3.8e-6 too high on one real kernel.
  out.lower = double(lower - HP(delta) * (1 + local[6]) - violation);
  // The witness: LDL^T of the local Hankel matrix, which must be positive definite.
  const HP uf = (HP(zf) - c) / s;
  HP h[4][4], l[4][4] = {}, d[4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) h[i][j] = local[i + j];
  for (int j = 0; j < 4; ++j) {
    d[j] = h[j][j];
    for (int k = 0; k < j; ++k) d[j] -= l[j][k] * l[j][k] * d[k];
    if (!(d[j] > 0)) return out;
    l[j][j] = 1;
    for (int i = j + 1; i < 4; ++i) {
      HP v = h[i][j];
      for (int k = 0; k < j; ++k) v -= l[i][k] * l[j][k] * d[k];
      l[i][j] = v / d[j];
    }
  }
  // H q = (1, u_f, u_f^2, u_f^3): the polynomial whose roots are the other nodes.
  HP q[4] = {1, uf, uf * uf, uf * uf * uf};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < i; ++k) q[i] -= l[i][k] * q[k];
  for (int i = 0; i < 4; ++i) q[i] /= d[i];
  for (int i = 3; i >= 0; --i)
    for (int k = i + 1; k < 4; ++k) q[i] -= l[k][i] * q[k];
  double guess[3];
  if (cubic_roots(double(q[3]), double(q[2]), double(q[1]), double(q[0]), guess) != 3) return out;
  HP nodes[4] = {uf, guess[0], guess[1], guess[2]};
  for (int i = 1; i < 4; ++i)
    for (int step = 0; step < 40; ++step) {
      const HP& x = nodes[i];
      const HP f = ((q[3] * x + q[2]) * x + q[1]) * x + q[0];
      const HP df = (3 * q[3] * x + 2 * q[2]) * x + q[1];
      if (df == 0) return out;
      nodes[i] = x - f / df;
    }
  HP weights[4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < i; ++k)
      if (nodes[i] == nodes[k]) return out;
    weights[i] = node_weight(local, nodes, 4, i);
    if (weights[i] < 0) return out;
  }
  // A witness only if it reproduces all seven moments (to 1e-30 of their size).
  for (int k = 0; k <= 6; ++k) {
    HP moment = 0;
    for (int i = 0; i < 4; ++i) moment += weights[i] * pow(nodes[i], k);
    if (abs(moment - local[k]) > HP("1e-30") * std::max(HP(1), abs(local[k]))) return out;
  }
  HP below = 0;
  for (int i = 1; i < 4; ++i)
    if (nodes[i] < uf) below += weights[i];
  out.inside = true;
  out.upper = double(below);
  out.upper_at = double(below + weights[0]);
  return out;
}

// The upper bound of six moments over their rounding box: G+ at the moments the closed form read,
// b~, is 1 - G of the mirrored problem (z -> -z: the mass behind z_f is the mass in front of -z_f,
// docs/reference.md §7), so the mirrored instance's continuous LP and witness bracket it as
// six_moment_bracket brackets G; the non-mirrored witness's mass at or below z_f bounds it from
// below as well. Compared is the closed form's G + w_1 on b~ itself.
void solve_upper_box(const VerifyInstance& inst, VerifyCase& c, lp::Backend& backend) {
  if (!std::isfinite(c.upper_floor)) return;  // the read moments have no witness
  const double* read = c.moments.data();
  const MsmBound<double> r = hamburger6(read, inst.zf);
  if (!std::isfinite(r.lower + r.at_zf)) return;
  std::vector<double> mirrored(inst.depths.size()), mirrored_read(6);
  for (size_t a = 0; a < mirrored.size(); ++a) mirrored[a] = -inst.depths[a];
  for (int k = 0; k < 6; ++k) mirrored_read[k] = k % 2 == 0 ? -read[k] : read[k];
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const lp::LocalPowerProblem problem{6, -kInf, kInf, lp::kContinuousSeedGrid};
  const lp::LocalPowerSolution local =
      lp::solve_power_locally(problem, mirrored, inst.weights, -inst.zf, backend);
  if (!local.solution.ok() || !local.solution.proven) return;
  const RoundedMomentBracket m =
      six_moment_bracket(mirrored_read, -inst.zf, local.solution.coefficients, local.solution.delta,
                         local.solution.violation, local.mean, local.scale);
  if (!m.inside) return;
  c.closed_upper = r.lower + r.at_zf;
  c.lp_upper = 1 - m.lower;
  // The closed form's own rounding moves G+ as the mirrored problem's certificate says (as
  // solve_continuous's allowance for G).
  long double rounding = 0;
  for (size_t j = 1; j < local.coefficients.size(); ++j) {
    long double scale = 0;
    for (size_t a = 0; a < mirrored.size(); ++a)
      scale += inst.weights[a] * std::pow(std::abs((long double)mirrored[a]), (long double)j);
    rounding += std::abs(local.coefficients[j]) * scale;
  }
  c.upper_rounding = std::min(kMaxRoundingAllowance, double(rounding * std::ldexp(1.0L, -49)));
  c.upper_floor = std::max(c.upper_floor, 1 - m.upper);
}

}  // namespace mb
