// Order-independent transparency (docs/transparency.md): the exact composite and every technique
// against analytic answers, the sharp bounds of the LP at every fragment, MBOIT's closed forms
// against the LP of the same basis, and order independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "oit/oit_verification.h"
#include "shadow/compositing.h"
#include "techniques/oit/oit_technique.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {
namespace {

struct Pixel {
  std::vector<double> depth, alpha;
  std::vector<Rgb> color;
  Rgb behind = {0.2f, 0.4f, 0.6f};
  PixelFragments view() const { return {depth, alpha, color, behind}; }
};

std::vector<double> warped(const Pixel& p) {
  const auto [lo, hi] = std::minmax_element(p.depth.begin(), p.depth.end());
  const DepthWarp w = DepthWarp::between(*lo, *hi);
  std::vector<double> u;
  for (double z : p.depth) u.push_back(w(z));
  return u;
}

TEST(OitCompositing, WarpsMapTheRangeOntoTheUnitInterval) {
  // Logarithmic: the geometric mean of the ends maps to 1/2; linear: the arithmetic mean.
  const DepthWarp log = DepthWarp::between(2, 8), lin = DepthWarp::between(2, 8, WarpKind::Linear);
  EXPECT_EQ(log(2), 0);
  EXPECT_EQ(log(8), 1);
  EXPECT_NEAR(log(4), 0.5, 1e-15);
  EXPECT_EQ(lin(2), 0);
  EXPECT_EQ(lin(8), 1);
  EXPECT_NEAR(lin(5), 0.5, 1e-15);
  EXPECT_NEAR(lin(4), 1.0 / 3, 1e-15);
  EXPECT_EQ(lin(9), 1);  // clamped
  EXPECT_EQ(DepthWarp::between(3, 3, WarpKind::Linear)(3), 0);
  EXPECT_EQ(warp_kind("linear"), WarpKind::Linear);
  EXPECT_THROW(warp_kind("cubic"), InputError);
}

Pixel random_pixel(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> unit(0, 1);
  Pixel p;
  for (int i = 0; i < count; ++i) {
    p.depth.push_back(2 + 10 * unit(rng));
    p.alpha.push_back(0.05 + 0.85 * unit(rng));
    p.color.push_back({float(unit(rng)), float(unit(rng)), float(unit(rng))});
  }
  return p;
}

std::vector<double> run(const std::string& name, const Pixel& p, OitParams params = {}) {
  auto technique = make_oit_technique(name, params);
  std::vector<double> t(p.depth.size());
  technique->transmittance(p.view(), warped(p), t);
  return t;
}

TEST(Oit, OneFragmentIsExactForEveryTechnique) {
  Pixel p;
  p.depth = {3};
  p.alpha = {0.4};
  p.color = {{1, 0, 0}};
  std::vector<std::string> names = oit_technique_names();
  names.push_back("lp:power4");
  for (const auto& name : names) {
    auto technique = make_oit_technique(name, {});
    std::vector<double> t(1);
    technique->transmittance(p.view(), warped(p), t);
    // Nothing lies in front of a lone fragment; normalised techniques composite it exactly too.
    const Rgb c = composite_with(*technique, p.view(), t);
    EXPECT_NEAR(c[0], 0.4 * 1 + 0.6 * 0.2, 1e-6) << name;
    EXPECT_NEAR(c[2], 0.6 * 0.6, 1e-6) << name;
    if (!technique->normalised()) {
      EXPECT_NEAR(t[0], 1.0, 1e-9) << name;
    }
  }
}

TEST(Oit, TwoFragmentsHaveTheAnalyticTransmittance) {
  Pixel p;
  p.depth = {7, 3};  // submitted back first
  p.alpha = {0.5, 0.3};
  p.color = {{0, 1, 0}, {1, 0, 0}};
  const std::vector<double> exact = run("exact", p);
  EXPECT_DOUBLE_EQ(exact[0], 0.7);  // behind the 0.3 fragment
  EXPECT_DOUBLE_EQ(exact[1], 1.0);
  // Submission order: the back fragment is drawn first, then covered: the same as sorted here.
  EXPECT_EQ(run("unsorted", p), exact);
  // The LP with the pixel's own depths among its points: two atoms are determined by four power
  // moments, so the sharp bound is exact.
  const std::vector<double> lp = run("lp:power4", p);
  EXPECT_NEAR(lp[0], 0.7, 1e-9);
  EXPECT_NEAR(lp[1], 1.0, 1e-9);
  // Reversed submission: unsorted blending now puts the far fragment on top.
  std::swap(p.depth[0], p.depth[1]);
  std::swap(p.alpha[0], p.alpha[1]);
  std::swap(p.color[0], p.color[1]);
  const std::vector<double> reversed = run("unsorted", p);
  EXPECT_DOUBLE_EQ(reversed[0], 0.5);  // the near fragment, covered by the far one
}

// The reference composite equals a back-to-front "over" blend of the sorted fragments.
TEST(Oit, ReferenceCompositeIsTheBackToFrontBlend) {
  std::mt19937_64 rng(43);
  for (int n = 0; n < 200; ++n) {
    const Pixel p = random_pixel(rng, 1 + n % 30);
    std::vector<double> t(p.depth.size());
    exact_transmittance(p.view(), t);
    const Rgb c = composite(p.view(), t, total_transmittance(p.view()));
    std::vector<size_t> order(p.depth.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return p.depth[a] > p.depth[b]; });
    double blend[3] = {p.behind[0], p.behind[1], p.behind[2]};
    for (size_t i : order)
      for (int k = 0; k < 3; ++k)
        blend[k] = p.alpha[i] * p.color[i][k] + (1 - p.alpha[i]) * blend[k];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], blend[k], 1e-6) << n;
  }
}

// e^{-A+} <= T_ref <= e^{-A-} at every fragment of random fragment sets (lp.beta 1 gives the
// maximum's side). MBOIT's closed form (beta = 0, bias 1e-10, which two fragments need: their four
// moments are singular without it) is Hamburger's bound on all of R: it equals the continuous LP on
// an interval wide enough to hold its canonical nodes (on [-40, 41] some lie beyond: 7e-6), and it
// is never sharper than the LP on the warp's own [0, 1] (the fragments' depths lie there; fewer
// distributions, more absorbance).
TEST(Oit, LpBoundsHoldAndMboitIsTheLpOnR) {
  std::mt19937_64 rng(44);
  OitParams sharp;
  sharp.technique.set("oit.beta", 0);
  sharp.technique.lp.grid = 4096;
  OitParams upper = sharp;
  upper.technique.lp_beta = 1;
  OitParams wide = sharp;
  wide.technique.lp = lp::Discretization{-400, 401, 256, false};
  wide.technique.lp.continuous = true;
  int compared = 0;
  double worst_r = 0, worst_interval = 0;
  for (int n = 0; n < 100; ++n) {
    const Pixel p = random_pixel(rng, 2 + n % 12);
    const std::vector<double> exact = run("exact", p), low = run("lp:power4", p, sharp),
                              high = run("lp:power4", p, upper), on_r = run("lp:power4", p, wide),
                              closed = run("mboit_power4", p, sharp);
    for (size_t l = 0; l < exact.size(); ++l) {
      EXPECT_GE(low[l], exact[l] - 1e-9) << n << " fragment " << l;
      EXPECT_LE(high[l], exact[l] + 1e-9) << n << " fragment " << l;
      EXPECT_GE(closed[l], low[l] - 1e-6) << n << " fragment " << l;
      EXPECT_NEAR(closed[l], on_r[l], 1e-6) << n << " fragment " << l;
      worst_r = std::max(worst_r, std::abs(closed[l] - on_r[l]));
      worst_interval = std::max(worst_interval, closed[l] - low[l]);
      ++compared;
    }
  }
  std::printf(
      "mboit_power4: %d fragments; vs the continuous LP on [-400, 401]: largest |dT| %.2e; "
      "above the LP on [0, 1] by up to %.3f\n",
      compared, worst_r, worst_interval);
}

// Six power moments likewise: mboit_power6 with beta = 0 is Hamburger's bound on R, the continuous
// LP on [-20, 21] (z^6 on a wider interval is numerically dependent with the constant; six
// moments' closed form loses digits on near-singular Hankel matrices, docs/reference.md §4, and
// a canonical node may lie beyond 21: hence 1e-5).
TEST(Oit, MboitPower6IsTheLpOnR) {
  std::mt19937_64 rng(47);
  OitParams sharp;
  sharp.technique.set("oit.beta", 0);
  OitParams wide = sharp;
  wide.technique.lp = lp::Discretization{-20, 21, 256, false};
  wide.technique.lp.continuous = true;
  double worst = 0;
  int compared = 0;
  for (int n = 0; n < 30; ++n) {
    const Pixel p = random_pixel(rng, 2 + n % 12);
    const std::vector<double> closed = run("mboit_power6", p, sharp),
                              on_r = run("lp:power6", p, wide);
    for (size_t l = 0; l < closed.size(); ++l, ++compared) {
      EXPECT_NEAR(closed[l], on_r[l], 1e-5) << n << " fragment " << l;
      worst = std::max(worst, std::abs(closed[l] - on_r[l]));
    }
  }
  std::printf("mboit_power6: %d fragments; vs the continuous LP on [-20, 21]: largest |dT| %.2e\n",
              compared, worst);
}

// MBOIT's trigonometric reconstruction (beta = 0) is the mass of one distribution with the pixel's
// moments, the canonical representation through the fragment, with the wrapping zone counted in
// part: it is never below the sharp lower bound on the circle, the continuous LP (certified) on u
// with the basis cos(k s u), sin(k s u), s = 2 pi - theta, over one period [0, 2 pi / s] with the
// zone behind; in T, trig <= the LP's e^{-A-}. Two and three moments (the LP engine takes up to 7
// functions; four moments' construction is checked in CanonicalBound).
TEST(Oit, MboitTrigIsNeverBelowTheSharpBoundOnTheCircle) {
  std::mt19937_64 rng(46);
  OitParams mboit;
  mboit.technique.set("oit.beta", 0);
  const double s = 2 * std::numbers::pi - mboit.wrapping_zone, period = 2 * std::numbers::pi / s;
  int compared = 0, sharp = 0;
  double worst_gap = 0;
  for (int n_moments = 2; n_moments <= 3; ++n_moments) {
    const std::string basis = mboit_trig_lp_basis(n_moments, mboit.wrapping_zone);
    OitParams lower = mboit;
    lower.technique.lp = lp::Discretization{0, period, 256, false};
    lower.technique.lp.continuous = true;
    for (int n = 0; n < 40; ++n) {
      const Pixel p = random_pixel(rng, 2 + n % 10);
      const std::vector<double> trig = run("mboit_trig" + std::to_string(n_moments), p, mboit),
                                low = run(basis, p, lower);
      for (size_t l = 0; l < trig.size(); ++l) {
        EXPECT_LE(trig[l], low[l] + 1e-7) << n_moments << " pixel " << n << " fragment " << l;
        worst_gap = std::max(worst_gap, low[l] - trig[l]);
        sharp += std::abs(low[l] - trig[l]) < 1e-6;
        ++compared;
      }
    }
  }
  std::printf(
      "mboit_trig2/3: %d fragments; at the sharp bound (1e-6) %d, below it in T by up to "
      "%.3f\n",
      compared, sharp, worst_gap);
}

// Permuting the fragments changes no moment-based answer (canonical summation: bit for bit), and
// changes unsorted blending.
TEST(Oit, MomentTechniquesDoNotDependOnTheOrder) {
  // The float variant sums in float in the canonical order, so it too is bit-identical.
  static const char* const kNames[] = {
      "mboit_power4",       "mboit_power6", "mboit_power8", "mboit_trig3_float",
      "mboit_power4_16bit", "lp:power4",    "wboit",        "unsorted"};
  std::mt19937_64 rng(45);
  int unsorted_changed = 0;
  for (int n = 0; n < 100; ++n) {
    Pixel p = random_pixel(rng, 3 + n % 10);
    std::vector<std::vector<double>> before;
    for (const char* name : kNames) before.push_back(run(name, p));
    std::vector<size_t> order(p.depth.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    Pixel q;
    q.behind = p.behind;
    for (size_t i : order)
      q.depth.push_back(p.depth[i]), q.alpha.push_back(p.alpha[i]), q.color.push_back(p.color[i]);
    int k = 0;
    for (const char* name : kNames) {
      const std::vector<double> after = run(name, q);
      bool same = true;
      for (size_t i = 0; i < order.size(); ++i) same &= after[i] == before[k][order[i]];
      if (std::string(name) == "unsorted")
        unsorted_changed += !same;
      else
        EXPECT_TRUE(same) << name << " pixel " << n;
      ++k;
    }
  }
  EXPECT_GT(unsorted_changed, 80);
}

TEST(Oit, ZeroWidthWarpAndEdgeOpacities) {
  // Every fragment at one depth: the warp maps all to 0, nothing lies in front of anything.
  Pixel p;
  p.depth = {4, 4, 4};
  p.alpha = {0.3, 0.0, 0.5};
  p.color = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  OitParams sharp;
  sharp.technique.set("oit.beta",
                      0);  // MBOIT's overestimation would count the fragments' own absorbance
  for (const char* name : {"exact", "mboit_power4", "lp:power4"}) {
    const std::vector<double> t = run(name, p, sharp);
    for (double v : t) EXPECT_NEAR(v, 1.0, 1e-9) << name;
  }
  // An opaque fragment handed to a moment technique stays finite (absorbance clamped at 10).
  p.depth = {3, 5};
  p.alpha = {1.0, 0.5};
  const std::vector<double> t = run("mboit_power4", p);
  for (double v : t) EXPECT_TRUE(std::isfinite(v));
  EXPECT_NEAR(run("exact", p)[1], 0.0, 0.0);
  EXPECT_THROW(make_oit_technique("mboit_power5", {}), InputError);
}

}  // namespace
}  // namespace mb
