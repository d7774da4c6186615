#include "soft/soft_techniques.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "moments/canonical.h"
#include "moments/chebyshev.h"
#include "moments/hamburger.h"
#include "soft/blocker_bounds.h"
#include "soft/summed_area.h"
#include "techniques/lp_technique.h"
#include "util/error.h"
#include "util/parallel_errors.h"

namespace mb {

const std::vector<std::string>& soft_technique_names() {
  static const std::vector<std::string> names{"pcss_exact", "pcss",     "pcss_vsm",
                                              "pcss_esm",   "pcss_csm", "msm_soft"};
  return names;
}

bool is_soft_technique(const std::string& name) {
  const auto& names = soft_technique_names();
  return std::find(names.begin(), names.end(), name) != names.end() ||
         soft_technique_solves_lp(name);
}

bool soft_technique_solves_lp(const std::string& name) {
  return name.rfind(kMsmSoftLp, 0) == 0;
}

namespace {

struct Receiver {
  int x = 0, y = 0;
  double zf = 0, slope = 0;  // slope: |dz/dx| + |dz/dy|
  double gx = 0, gy = 0;
  double cx() const { return x + 0.5; }
  double cy() const { return y + 0.5; }
};

// What a view's receivers share: the map, the light, the protocol's bias and kernel, and the
// filter limits.
struct SoftContext {
  const ShadowMap& map;
  const SoftReceivers& soft;
  const GaussianKernel& kernel;
  const BiasParams& bias;
  const SoftParams& params;
  double kernel_variance = 0;  // per axis, of the protocol's discrete kernel
  // The protocol's bias (docs/reference.md §3) for a filter reaching `radius` texels: the
  // receiver's plane stays behind z_f - delta at every texel the filter reads.
  double test_depth(const Receiver& r, double radius) const {
    return r.zf - (bias.constant + bias.slope * radius * r.slope);
  }
  // A search-region texel is a blocker where the protocol's own test would count it, the bias of
  // the kernel's reach (docs/soft-shadows.md §2): a bias grown with the region drops the nearest
  // blockers, and with them the contact shadows, while the reference keeps them.
  double search_depth(const Receiver& r) const { return test_depth(r, kernel.radius()); }
  // Texels a side of PCSS's search region: the option, or (0) seed 001's region from the light's
  // size, the light's cone from the receiver back to the depth range's near end (z = 0).
  int pcss_search(const Receiver& r) const {
    if (params.pcss_search > 0) return params.pcss_search;
    return int(std::min(2 * std::ceil(soft.rim_shear * r.zf) + 1, 255.0));
  }
  // PCSS's penumbra for a directional light (seed 001, its directional form): the blockers' light
  // cone widens by 2 tan(theta / 2) per unit of depth, here in texels; clamped to the filter range.
  double penumbra(const Receiver& r, double blocker_depth) const {
    const double w = 2 * soft.rim_shear * std::max(r.zf - blocker_depth, 0.0);
    return std::clamp(w, params.min_filter, double(params.max_filter));
  }
  // The box a technique that filters with one box uses for the penumbra w: the variance of the
  // penumbra's box and the protocol's kernel together (docs/soft-shadows.md §2), the box of
  // width W over texels having (W^2 - 1) / 12.
  double box_width(double w) const {
    return std::min(std::sqrt(w * w + 12 * kernel_variance + 1), double(params.max_filter));
  }
};

// Every texel (i, j) the square of side w centred on (cx, cy) overlaps, with the overlap's extent
// along x and y: the exact box filter weights it by wx wy / w^2.
template <class F>
void for_each_box_texel(double cx, double cy, double w, F&& f) {
  const double ax = cx - w / 2, bx = cx + w / 2, ay = cy - w / 2, by = cy + w / 2;
  for (int j = int(std::floor(ay)); j < int(std::ceil(by)); ++j) {
    const double wy = std::min(by, j + 1.0) - std::max(ay, double(j));
    for (int i = int(std::floor(ax)); i < int(std::ceil(bx)); ++i)
      f(i, j, std::min(bx, i + 1.0) - std::max(ax, double(i)), wy);
  }
}

// The exact box filter: every texel the square of side w centred on (cx, cy) overlaps, weighted
// by the overlap's area, tested against the receiver's plane through depth z at the centre
// (gradient g in depth per texel); below a texel's width, the texel under the centre.
double box_pcf(const ShadowMap& map, double cx, double cy, double w, double z, double gx,
               double gy) {
  if (w < 1e-9) return texel_cdf(map, int(std::floor(cx)), int(std::floor(cy)), z);
  double sum = 0;
  for_each_box_texel(cx, cy, w, [&](int i, int j, double wx, double wy) {
    const double zj = z + gy * (j + 0.5 - cy);
    sum += wx * wy * texel_cdf(map, i, j, zj + gx * (i + 0.5 - cx));
  });
  return std::min(sum / (w * w), 1.0);
}

// The penumbra's box seen through the protocol's kernel: each kernel tap at the protocol's biased
// depth, as the reference tests it, widened to the exact box of width w over which the depth
// follows the receiver's plane (docs/soft-shadows.md §2). The reference is the area light's
// visibility under the kernel, so a light of no extent gives the protocol's PCF exactly; the
// plane keeps a wide box off the receiver's own surface without a bias grown with the box.
double kernel_box_pcf(const SoftContext& c, const Receiver& r, double w) {
  const int k = c.kernel.radius();
  const double z = c.test_depth(r, k);
  double sum = 0;
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      sum += c.kernel.weight(dx, dy) * box_pcf(c.map, r.cx() + dx, r.cy() + dy, w, z, r.gx, r.gy);
  return std::min(sum, 1.0);
}

// PCSS computed exactly (docs/soft-shadows.md §2): every texel of the search region, the exact
// mean of the blockers' depths, the exact box filter under the protocol's kernel.
double pcss_exact(const SoftContext& c, const Receiver& r) {
  const int side = c.pcss_search(r), half = side / 2;
  const double z = c.search_depth(r);
  double sum = 0, count = 0;
  for (int j = r.y - half; j < r.y - half + side; ++j)
    for (int i = r.x - half; i < r.x - half + side; ++i) {
      const double d = c.map.at(i, j);
      if (d < z) sum += d, count += 1;
    }
  if (count == 0) return 0;  // seed 001: no blocker, no shadow
  return kernel_box_pcf(c, r, c.penumbra(r, sum / count));
}

// PCSS as seed 001 runs it: point taps spread evenly over the search region and over the filter.
double pcss_sampled(const SoftContext& c, const Receiver& r) {
  const int nb = c.params.blocker_taps, nf = c.params.filter_taps;
  const double span = c.pcss_search(r) - 1;
  const double zs = c.search_depth(r);
  double sum = 0, count = 0;
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < nb; ++i) {
      const double u = nb == 1 ? 0 : double(i) / (nb - 1) - 0.5,
                   v = nb == 1 ? 0 : double(j) / (nb - 1) - 0.5;
      const double d =
          c.map.at(int(std::floor(r.cx() + u * span)), int(std::floor(r.cy() + v * span)));
      if (d < zs) sum += d, count += 1;
    }
  if (count == 0) return 0;
  // Taps over the penumbra's box widened by the kernel, against the receiver's plane.
  const double w = c.box_width(c.penumbra(r, sum / count)), z = c.test_depth(r, c.kernel.radius());
  double shadow = 0;
  for (int j = 0; j < nf; ++j)
    for (int i = 0; i < nf; ++i) {
      const double u = (i + 0.5) / nf - 0.5, v = (j + 0.5) / nf - 0.5;
      const int tx = int(std::floor(r.cx() + u * w)), ty = int(std::floor(r.cy() + v * w));
      shadow += texel_cdf(c.map, tx, ty, z + r.gx * (tx - r.x) + r.gy * (ty - r.y));
    }
  return std::min(shadow / (nf * nf), 1.0);
}

// The SAT techniques' per-texel values: E over the texel's atoms of each function of depth
// (one atom, the layer-0 depth, on an opaque map; docs/reference.md §7 on a translucent one).
template <class F>
std::vector<double> texel_values(const ShadowMap& map, int channels, F&& f) {
  std::vector<double> values(map.depth.size() * channels, 0.0), one(channels);
  for (size_t t = 0; t < map.depth.size(); ++t) {
    if (!map.translucent()) {
      f(map.depth[t], values.data() + t * channels);
      continue;
    }
    for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a) {
      f(map.atom_depth[a], one.data());
      for (int k = 0; k < channels; ++k) values[t * channels + k] += map.blended_mass()[a] * one[k];
    }
  }
  return values;
}

// The blocker search's integer box: the search region matched to the texel grid (seed 004 §3.6).
void search_mean(const SummedAreaTable& sat, const Receiver& r, int side, double* mean) {
  const int x0 = r.x - side / 2, y0 = r.y - side / 2;
  sat.box_mean(x0, y0, x0 + side, y0 + side, mean);
}

void filter_mean(const SummedAreaTable& sat, const Receiver& r, double w, double* mean) {
  sat.rect_mean(r.cx() - w / 2, r.cy() - w / 2, r.cx() + w / 2, r.cy() + w / 2, mean);
}

// The one-depth blocker estimate of a region whose lit share is p at z_s and whose mean depth
// is mu: the rest, at one depth, averages (mu - p z_s) / (1 - p); none when p is (nearly) 1.
bool blocker_from_lit_share(double mu, double p, double zs, double* blocker) {
  if (1 - p < 1e-6) return false;
  *blocker = std::clamp((mu - p * zs) / (1 - p), 0.0, zs);
  return true;
}

// Variance soft shadows (seed 001 PCSS + SAVSM; the blocker search of Yang et al.'s VSSM): the
// search region's mean and variance bound the lit share p by Cantelli; the rest, at one depth,
// must average (mu - p z) / (1 - p).
double pcss_vsm(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r) {
  double b[2];
  search_mean(sat, r, c.params.sat_search, b);
  const double zs = c.search_depth(r);
  if (zs <= b[0]) return 0;  // the mean lies behind the receiver: Cantelli bounds nothing
  const double variance = std::max(b[1] - b[0] * b[0], 0.0);
  const double lit = variance / (variance + (zs - b[0]) * (zs - b[0]));
  double blocker = 0;
  if (!blocker_from_lit_share(b[0], lit, zs, &blocker)) return 0;
  const double w = c.box_width(c.penumbra(r, blocker));
  filter_mean(sat, r, w, b);
  return vsm_bound(b, c.test_depth(r, w / 2), 0.0);
}

// ESM through a summed-area table (seed 001 "PCSS + ESM"): channels exp(c (z - 1)) and z. The lit
// share at depth d is E[exp(c (z - d))], clamped to 1 (seed 002); the blocker search takes it at
// z_s and the rest of the region at one depth, as pcss_vsm does.
double pcss_esm(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r) {
  const double k = c.params.esm_c;
  const auto lit = [&](const double* b, double d) {
    return std::min(b[0] * std::exp(k * (1 - d)), 1.0);
  };
  double b[2];
  search_mean(sat, r, c.params.sat_search, b);
  const double zs = c.search_depth(r);
  double blocker = 0;
  if (!blocker_from_lit_share(b[1], lit(b, zs), zs, &blocker)) return 0;
  const double w = c.box_width(c.penumbra(r, blocker));
  filter_mean(sat, r, w, b);
  return 1 - lit(b, c.test_depth(r, w / 2));
}

// CSM's channels per term k = 1..M, c_k = (2k - 1) pi: cos(c_k z), sin(c_k z), z cos(c_k z),
// z sin(c_k z); then z. Each in [-1, 1], stored as (v + 1) / 2 in the table.
void csm_channels(int terms, double z, double* v) {
  for (int k = 0; k < terms; ++k) {
    const double ck = (2 * k + 1) * std::numbers::pi;
    v[4 * k] = std::cos(ck * z), v[4 * k + 1] = std::sin(ck * z);
    v[4 * k + 2] = z * v[4 * k], v[4 * k + 3] = z * v[4 * k + 1];
  }
  v[4 * terms] = z;
  for (int i = 0; i <= 4 * terms; ++i) v[i] = (v[i] + 1) / 2;
}

// Seed 001's CSM test, the Fourier series of the step H(z - d) truncated at M terms, each
// attenuated by exp(-alpha (k / M)^2) against ringing, on filtered channels `m` (unscaled):
// f = 1/2 + 2 sum_k a_k / c_k (cos(c_k d) E[sin(c_k z)] - sin(c_k d) E[cos(c_k z)]). `offset`
// 2 reads E[z cos], E[z sin] instead, giving E[z f] without its 1/2 E[z] term.
double csm_series(const SoftContext& c, const double* m, double d, int offset) {
  const int terms = c.params.csm_terms;
  double sum = 0;
  for (int k = 0; k < terms; ++k) {
    const double ck = (2 * k + 1) * std::numbers::pi;
    const double a = std::exp(-c.params.csm_absorption * double(k + 1) * (k + 1) / (terms * terms));
    sum +=
        a / ck * (std::cos(ck * d) * m[4 * k + offset + 1] - std::sin(ck * d) * m[4 * k + offset]);
  }
  return 2 * sum;
}

// CSM through a summed-area table (seed 001 "SACSM"): the lit share saturate(2 f) (seed 001 scales
// by 2 so that f = 1/2 at d = z reads lit); the blocker search averages z over the region weighted
// by CSM's own shadow estimate 1 - f at z_s, E[z (1 - f)] / E[1 - f], from the z cos and z sin
// channels (docs/soft-shadows.md §2).
double pcss_csm(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r) {
  const int n = 4 * c.params.csm_terms + 1;
  std::vector<double> m(n);
  search_mean(sat, r, c.params.sat_search, m.data());
  for (double& v : m) v = 2 * v - 1;
  const double zs = c.search_depth(r), mu = m[n - 1];
  const double shadowed = 0.5 - csm_series(c, m.data(), zs, 0);       // E[1 - f]
  const double weighted = 0.5 * mu - csm_series(c, m.data(), zs, 2);  // E[z (1 - f)]
  if (shadowed < 1e-6) return 0;
  const double blocker = std::clamp(weighted / shadowed, 0.0, zs);
  const double w = c.box_width(c.penumbra(r, blocker));
  filter_mean(sat, r, w, m.data());
  for (double& v : m) v = 2 * v - 1;
  const double f = 0.5 + csm_series(c, m.data(), c.test_depth(r, w / 2), 0);
  return 1 - std::clamp(2 * f, 0.0, 1.0);
}

// Moment soft shadow mapping (seed 004 §3): the search region's four moments, biased by alpha,
// give the canonical three-atom distribution through z_s; its atoms in front of z_s are the
// blockers, their mean depth softened towards z_s by eps_z1; above 1 - eps_u they are umbra.
struct MsmBlocker {
  double depth = 0;   // seed 004's estimate, eps_z1 included
  double weight = 0;  // the canonical distribution's mass in front of z_s
  double zs = 0;
};

MsmBlocker msm_blocker(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r) {
  const double star[4] = {0.5, 0.5, 0.5, 0.5};
  double b[4];
  search_mean(sat, r, c.params.sat_search, b);
  bias_moments(b, 4, c.params.msm_alpha, star);
  MsmBlocker out;
  out.zs = c.search_depth(r);
  const MsmBound<double> canonical = hamburger4(b, out.zs);
  double sum = 0;
  for (int i = 1; i < canonical.node_count; ++i)
    if (canonical.nodes[i] < out.zs)
      out.weight += canonical.weights[i], sum += canonical.weights[i] * canonical.nodes[i];
  const double eps = c.params.blocker_epsilon;
  out.depth = (eps * out.zs + sum) / (eps + out.weight);
  return out;
}

double msm_soft(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r) {
  const MsmBlocker blocker = msm_blocker(c, sat, r);
  if (blocker.weight > 1 - c.params.umbra_epsilon) return 1;
  const double w = c.box_width(c.penumbra(r, blocker.depth));
  const double star[4] = {0.5, 0.5, 0.5, 0.5};
  double b[4];
  filter_mean(sat, r, w, b);
  bias_moments(b, 4, c.params.msm_alpha, star);
  return std::clamp(hamburger4(b, c.test_depth(r, w / 2)).lower, 0.0, 1.0);
}

// The box's own distribution: every texel (each atom, on a translucent map) the square of side w
// centred on the receiver overlaps, weighted by the overlap over w^2, the weights with which
// seed 004's interpolated query takes the box's moments from the table (docs/soft-shadows.md §2).
void box_distribution(const ShadowMap& map, double cx, double cy, double w,
                      std::vector<double>& depths, std::vector<double>& weights) {
  depths.clear(), weights.clear();
  for_each_box_texel(cx, cy, w, [&](int i, int j, double wx, double wy) {
    const double share = wx * wy / (w * w);
    if (!(share > 0)) return;
    if (!map.translucent() || i < 0 || j < 0 || i >= map.width || j >= map.height) {
      depths.push_back(map.at(i, j)), weights.push_back(share);
      return;
    }
    const size_t t = size_t(j) * map.width + i;
    for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a)
      depths.push_back(map.atom_depth[a]), weights.push_back(share * map.blended_mass()[a]);
  });
}

// One thread's LP state for msm_soft:lp:<basis>: its backend and the storage every receiver
// reuses.
struct LpFinalStep {
  std::unique_ptr<lp::Backend> backend;
  std::vector<double> depths, weights;
  lp::Problem problem;
  lp::Solution solution;
};

// msm_soft with Problem 1 as its final step (docs/soft-shadows.md §2): seed 004's blocker search
// and box, then the sharpest lower bound the box's moments in `factory`'s basis allow, on the grid
// and the box's own depths, solved cold (any schedule gives these bits). The box's distribution is
// one of those the LP ranges over, so below the umbra skip the answer never exceeds the box filter
// at the same depth. NaN when the LP gives no certified answer.
double msm_soft_lp(const SoftContext& c, const SummedAreaTable& sat, const Receiver& r,
                   const lp::ProblemFactory& factory, LpFinalStep& step) {
  const MsmBlocker blocker = msm_blocker(c, sat, r);
  if (blocker.weight > 1 - c.params.umbra_epsilon) return 1;
  const double w = c.box_width(c.penumbra(r, blocker.depth)), z = c.test_depth(r, w / 2);
  box_distribution(c.map, r.cx(), r.cy(), w, step.depths, step.weights);
  // F_Z(z) = 0: no distribution with these moments needs mass in front of z (the LP's exact skip).
  if (std::all_of(step.depths.begin(), step.depths.end(), [&](double d) { return d >= z; }))
    return 0;
  step.problem = factory.from_distribution(step.depths, step.weights, z);
  step.backend->solve_into(step.problem, nullptr, step.solution);
  const lp::Solution& s = step.solution;
  if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal)
    return std::numeric_limits<double>::quiet_NaN();
  return std::clamp(s.G, 0.0, 1.0);
}

std::unique_ptr<SummedAreaTable> build_sat(const std::string& name, const ShadowMap& map,
                                           const SoftParams& p) {
  const SatPrecision precision = p.sat == "exact" ? SatPrecision::Exact : SatPrecision::Fixed32;
  const int side = std::max(p.sat_search, p.max_filter + 2);
  const int64_t n = int64_t(side) * side;
  const int pad = side / 2 + 2;
  if (name == "pcss_vsm") {
    auto f = [](double z, double* v) { v[0] = z, v[1] = z * z; };
    double far[2];
    f(1.0, far);
    return std::make_unique<SummedAreaTable>(texel_values(map, 2, f), map.width, map.height, 2,
                                             std::vector<double>(far, far + 2), pad, n, precision);
  }
  if (name == "pcss_esm") {
    auto f = [c = p.esm_c](double z, double* v) { v[0] = std::exp(c * (z - 1)), v[1] = z; };
    return std::make_unique<SummedAreaTable>(texel_values(map, 2, f), map.width, map.height, 2,
                                             std::vector<double>{1.0, 1.0}, pad, n, precision);
  }
  if (name == "pcss_csm") {
    const int channels = 4 * p.csm_terms + 1;
    auto f = [terms = p.csm_terms](double z, double* v) { csm_channels(terms, z, v); };
    std::vector<double> far(channels);
    csm_channels(p.csm_terms, 1.0, far.data());
    return std::make_unique<SummedAreaTable>(texel_values(map, channels, f), map.width, map.height,
                                             channels, far, pad, n, precision);
  }
  auto f = [](double z, double* v) { v[0] = z, v[1] = z * z, v[2] = v[1] * z, v[3] = v[2] * z; };
  return std::make_unique<SummedAreaTable>(texel_values(map, 4, f), map.width, map.height, 4,
                                           std::vector<double>(4, 1.0), pad, n, precision);
}

}  // namespace

namespace {

SoftContext make_context(const ShadowMap& map, const SoftReceivers& soft,
                         const GaussianKernel& kernel, const BiasParams& bias,
                         const SoftParams& params) {
  SoftContext context{map, soft, kernel, bias, params};
  for (int d = -kernel.radius(); d <= kernel.radius(); ++d)
    context.kernel_variance += kernel.weights[d + kernel.radius()] * d * d;
  return context;
}

Receiver receiver_of(const Fragments& f, const SoftReceivers& soft, size_t k) {
  Receiver r;
  r.x = int(f.texel[k] % f.width);
  r.y = int(f.texel[k] / f.width);
  r.zf = f.zf[k];
  r.slope = std::abs(soft.gx[k]) + std::abs(soft.gy[k]);
  r.gx = soft.gx[k], r.gy = soft.gy[k];
  return r;
}

}  // namespace

namespace {

// msm_soft:lp:<basis>'s factory: the basis of its lp: part on lp.lo, lp.hi and lp.grid.
std::unique_ptr<lp::ProblemFactory> lp_final_step_factory(const std::string& name,
                                                          const TechniqueParams& technique) {
  const std::string lp_name = name.substr(std::string(kMsmSoftLp).size() - 3);
  if (lp_name == "lp:")
    throw InputError("technique '" + name + "': expected " + kMsmSoftLp + "<basis>, e.g. " +
                     kMsmSoftLp + "power4");
  if (technique.lp.continuous || technique.lp.quantize)
    throw InputError("lp.discretization: " + name +
                     " solves on the grid and the box's own depths; expected lp.discretization "
                     "grid (docs/soft-shadows.md §2)");
  const Basis basis = Basis::parse(lp_technique_basis(lp_name));
  lp::check_backend_rows(technique.lp_backend, int(basis.size()), "techniques: " + name);
  return std::make_unique<lp::ProblemFactory>(basis, technique.lp);
}

}  // namespace

void check_soft_technique(const std::string& name, const TechniqueParams& technique) {
  if (soft_technique_solves_lp(name)) lp_final_step_factory(name, technique);
}

SoftResult soft_shadow(const std::string& name, const ShadowMap& map, const Fragments& fragments,
                       const SoftReceivers& soft, const GaussianKernel& kernel,
                       const BiasParams& bias, const SoftParams& params, int threads,
                       const TechniqueParams& technique) {
  if (!is_soft_technique(name)) throw InputError("technique '" + name + "' is no soft technique");
  if (soft.angle_deg <= 0)
    throw InputError("techniques: " + name +
                     " estimates a penumbra and needs a light with an extent; expected "
                     "light.angle > 0 or a dataset with light_angles (docs/soft-shadows.md)");
  const SoftContext context = make_context(map, soft, kernel, bias, params);
  std::unique_ptr<SummedAreaTable> sat;
  if (name != "pcss" && name != "pcss_exact") sat = build_sat(name, map, params);
  const bool lp_step = soft_technique_solves_lp(name);
  std::unique_ptr<lp::ProblemFactory> factory;
  if (lp_step) factory = lp_final_step_factory(name, technique);
  std::vector<double> shadow(fragments.size());
  ParallelErrors errors;
  size_t failures = 0;
#pragma omp parallel num_threads(threads) reduction(+ : failures)
  {
    // GLPK, the fast backend's fallback, frees memory only in the thread that allocated it: each
    // thread makes, uses and drops its own LP state.
    LpFinalStep step;
    if (lp_step) errors.capture([&] { step.backend = lp::make_backend(technique.lp_backend); });
#pragma omp for schedule(dynamic, 1024)
    for (size_t k = 0; k < fragments.size(); ++k)
      errors.capture([&] {
        if (lp_step && !step.backend) return;  // its error is captured already
        const Receiver r = receiver_of(fragments, soft, k);
        if (name == "pcss_exact")
          shadow[k] = pcss_exact(context, r);
        else if (name == "pcss")
          shadow[k] = pcss_sampled(context, r);
        else if (name == "pcss_vsm")
          shadow[k] = pcss_vsm(context, *sat, r);
        else if (name == "pcss_esm")
          shadow[k] = pcss_esm(context, *sat, r);
        else if (name == "pcss_csm")
          shadow[k] = pcss_csm(context, *sat, r);
        else if (lp_step)
          shadow[k] = msm_soft_lp(context, *sat, r, *factory, step);
        else
          shadow[k] = msm_soft(context, *sat, r);
        // A closed form on rounded moments can leave its domain (a Hankel matrix no longer
        // positive definite), an LP its certificate: no answer, counted, the receiver unshadowed.
        if (!std::isfinite(shadow[k])) shadow[k] = 0, ++failures;
      });
  }
  errors.rethrow();
  return {std::move(shadow), failures};
}

std::vector<BlockerAuditRow> blocker_audit(const ShadowMap& map, const Fragments& fragments,
                                           const SoftReceivers& soft, const GaussianKernel& kernel,
                                           const BiasParams& bias, const SoftParams& params,
                                           int threads) {
  std::vector<BlockerAuditRow> rows;
  if (params.audit == 0 || fragments.size() == 0) return rows;
  const SoftContext context = make_context(map, soft, kernel, bias, params);
  const auto sat = build_sat("msm_soft", map, params);
  lp::Discretization grid;
  grid.grid = 256;
  const lp::ProblemFactory factory(Basis::parse({"power4"}), grid);
  const size_t stride = std::max<size_t>(1, fragments.size() / size_t(params.audit));
  std::vector<size_t> picked;
  for (size_t k = stride / 2; k < fragments.size(); k += stride) picked.push_back(k);
  std::vector<BlockerAuditRow> found(picked.size());
  std::vector<char> kept(picked.size(), 0);
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  {
    // One backend per thread, made and dropped in it (GLPK's memory is the thread's); every solve
    // starts cold, so the schedule changes no answer.
    std::unique_ptr<lp::Backend> backend;
    errors.capture([&] { backend = lp::make_backend("fast"); });
#pragma omp for schedule(dynamic, 1)
    for (size_t p = 0; p < picked.size(); ++p)
      errors.capture([&] {
        if (!backend) return;
        const Receiver r = receiver_of(fragments, soft, picked[p]);
        const MsmBlocker seed = msm_blocker(context, *sat, r);
        // The search region as its texels: their depths join the grid, its moments are theirs.
        const int side = params.sat_search, x0 = r.x - side / 2, y0 = r.y - side / 2;
        std::vector<double> depths;
        double mass = 0, sum = 0;
        for (int y = y0; y < y0 + side; ++y)
          for (int x = x0; x < x0 + side; ++x) {
            const double z = map.at(x, y);
            depths.push_back(z);
            if (z < seed.zs) mass += 1, sum += z;
          }
        if (mass == 0) return;
        const std::vector<double> weights(depths.size(), 1.0 / double(depths.size()));
        const BlockerBounds bounds =
            blocker_bounds_dinkelbach(factory, depths, weights, seed.zs, *backend);
        if (!bounds.feasible) return;
        BlockerAuditRow& row = found[p];
        row.receiver = picked[p];
        row.zs = seed.zs;
        row.exact = sum / mass;
        row.seed = seed.depth;
        row.lo = bounds.lo, row.hi = bounds.hi;
        // Both sides start from the region's own mean, so lo <= exact <= hi.
        row.penumbra_lo = 2 * soft.rim_shear * std::max(r.zf - bounds.hi, 0.0);
        row.penumbra_hi = 2 * soft.rim_shear * std::max(r.zf - bounds.lo, 0.0);
        row.penumbra_exact = 2 * soft.rim_shear * std::max(r.zf - row.exact, 0.0);
        row.penumbra_seed = 2 * soft.rim_shear * std::max(r.zf - row.seed, 0.0);
        kept[p] = 1;
      });
  }
  errors.rethrow();
  for (size_t p = 0; p < picked.size(); ++p)
    if (kept[p]) rows.push_back(found[p]);
  return rows;
}

}  // namespace mb
