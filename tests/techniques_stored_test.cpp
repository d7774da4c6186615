// The stored techniques (docs/reference.md §8) beside lp_stored:<technique>, Problem 1 over the
// moment box of the same format: the LP's answer is the sharpest lower bound the stored values
// allow, so a closed form reading the map should not claim more shadow, and where it does the
// format (not the LP) is to blame. The transform is what keeps a 16-bit map usable (seed 000
// §4.3): without it, short-range shadows over-darken.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "moments/storage.h"
#include "scene/procedural.h"
#include "techniques/registry.h"
#include "techniques/technique.h"
#include "util/error.h"

namespace mb {
namespace {

struct Kernel {
  std::vector<double> depths, weights;
  double zf = 0;
};

// A kernel as a map filters it: up to 8 depths, or (short-range shadows) an occluder and a
// receiver a little behind it, z_f between them just in front of the receiver (as the depth bias
// puts a receiver's own fragments).
Kernel random_kernel(SeededRandom& rng, int trial, bool short_range) {
  Kernel k;
  double total = 0;
  if (short_range) {
    const double occluder = rng.uniform(0.05, 0.95), gap = rng.uniform(2e-4, 5e-3);
    k.depths = {occluder, std::min(occluder + gap, 1.0)};
    k.weights = {rng.uniform(0.05, 0.95), 0};
    k.weights[1] = 1 - k.weights[0];
    k.zf = k.depths[1] - gap * rng.uniform(0.02, 0.5);
    return k;
  }
  for (int t = 0; t < 1 + trial % 8; ++t) {
    k.depths.push_back(rng.uniform(0.001, 0.999));
    k.weights.push_back(rng.uniform(0.05, 1));
    total += k.weights.back();
  }
  for (double& w : k.weights) w /= total;
  k.zf = rng.uniform(0.001, 0.999);
  return k;
}

// G of `technique` for the kernel as its map stores it.
double stored_shadow(Technique& technique, const Kernel& k) {
  std::vector<double> q =
      filtered_stored_values(technique.storage(), technique.basis(), k.depths, k.weights);
  load_moments(technique.storage(), q);
  FragmentInput in;
  in.moments = q;
  in.zf = k.zf;
  in.kernel_depths = k.depths;
  in.kernel_weights = k.weights;
  return technique.shadow(in);
}

double cdf(const Kernel& k) {
  double s = 0;
  for (size_t t = 0; t < k.depths.size(); ++t) s += k.depths[t] < k.zf ? k.weights[t] : 0;
  return s;
}

// Every hard-shadow row with a unorm map, at its option defaults, against the LP of its format:
// the LP never claims more than the kernel holds (its box holds the kernel's own moments), and
// the closed form rarely claims more than the LP.
TEST(StoredTechniques, ClosedFormsStayBelowTheLpOfTheirFormat) {
  const TechniqueParams params;
  int rows = 0;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow)) {
    if (row->prefix() || row->storage.rfind("unorm", 0) != 0) continue;
    ++rows;
    auto technique = make_technique(row->name, params);
    auto lp = make_technique("lp_stored:" + row->name, params);
    EXPECT_EQ(lp->storage().name(), technique->storage().name());
    EXPECT_EQ(lp->basis().names(), technique->basis().names());
    SeededRandom rng(63);
    int above = 0;
    const int n = 120;
    for (int trial = 0; trial < n; ++trial) {
      const Kernel k = random_kernel(rng, trial, false);
      const double g = stored_shadow(*technique, k), bound = stored_shadow(*lp, k);
      ASSERT_LE(bound, cdf(k) + 1e-6) << row->name << " trial " << trial;
      above += g > bound + 1e-4;
    }
    // A box LP that failed answers 0 and would pass the soundness check above as a lit fragment.
    EXPECT_EQ(lp->failures(), 0u) << row->name;
    std::printf("%s: above the LP of its format in %d of %d kernels\n", row->name.c_str(), above,
                n);
    // Without a transform the rounding of the raw powers leaves the closed form claiming more
    // than the stored values allow in half of the kernels; theta_4 and theta_2 keep it rare at
    // 16 bits. Six moments at 10 bits claim more in a fifth of them even at seed 004's
    // alpha 4e-3 ("a serious problem for hard shadows", seed 004 §2.5).
    if (technique->storage().transform.isIdentity())
      EXPECT_GE(above, n / 4) << row->name;
    else if (technique->storage().bits == 16)
      EXPECT_LE(above, n / 20) << row->name;
    else
      EXPECT_LE(above, n / 3) << row->name;
  }
  EXPECT_GE(rows, 5);  // hamburger4_16bit and its canonical twin, hausdorff4_16bit, vsm_16bit,
                       // hamburger6_10bit
}

// Seed 000 §4.3: 16 bits of the raw powers give "unacceptable artifacts", theta_4 makes them
// usable. On short-range shadows the canonical map's rounding moves the moments so far that the
// closed form claims far more shadow than the kernel holds; theta_4's does not.
TEST(StoredTechniques, Theta4KeepsShortRangeShadowsThatTheCanonicalMapDarkens) {
  const TechniqueParams params;
  auto theta4 = make_technique("hamburger4_16bit", params);
  auto canonical = make_technique("hamburger4_16bit_canonical", params);
  SeededRandom rng(64);
  double worst_theta4 = 0, worst_canonical = 0;
  int dark_theta4 = 0, dark_canonical = 0;
  const int n = 2000;
  for (int trial = 0; trial < n; ++trial) {
    const Kernel k = random_kernel(rng, trial, true);
    const double truth = cdf(k);
    const double a = stored_shadow(*theta4, k) - truth, b = stored_shadow(*canonical, k) - truth;
    worst_theta4 = std::max(worst_theta4, a), worst_canonical = std::max(worst_canonical, b);
    dark_theta4 += a > 0.01, dark_canonical += b > 0.01;
  }
  std::printf("over-darkening > 0.01: theta_4 %d, canonical %d of %d; worst %.4f, %.4f\n",
              dark_theta4, dark_canonical, n, worst_theta4, worst_canonical);
  EXPECT_GT(dark_canonical, 5 * std::max(dark_theta4, 1));
  EXPECT_GT(worst_canonical, 1.5 * worst_theta4);
}

TEST(StoredTechniques, LpStoredRefusesTechniquesWithoutAStoredFormat) {
  const TechniqueParams params;
  for (const char* name :
       {"lp_stored:hamburger4", "lp_stored:lp:power4", "lp_stored:nonsense", "lp_stored:"}) {
    try {
      make_technique(name, params);
      FAIL() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("hamburger4_16bit"), std::string::npos) << e.what();
    }
  }
  TechniqueParams beta = params;
  beta.lp_beta = 0.5;
  EXPECT_THROW(make_technique("lp_stored:hamburger4_16bit", beta), InputError);
}

}  // namespace
}  // namespace mb
