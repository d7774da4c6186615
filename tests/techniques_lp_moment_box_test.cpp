// lp.moment_box for any basis (techniques/lp_fragment_solver.h, docs/reference.md §8): a unorm
// box after lp.moment_transform. `seed` keeps what unorm16 meant before the transforms could be
// chosen (seed 000's theta_4 verbatim), `canonical` is the identity for power moments, `optimized`
// the basis's own search; the choice is part of a sweep's identity.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "eval/eval_config.h"
#include "moments/quantization_transform.h"
#include "moments/storage.h"
#include "sweep/run_identity.h"
#include "sweep/sweep_run.h"
#include "techniques/lp_fragment_solver.h"
#include "techniques/lp_technique.h"
#include "techniques/technique.h"
#include "util/error.h"

namespace mb {
namespace {

TEST(LpMomentBox, SeedKeepsTheta4AndOtherTransformsReachAnyBasis) {
  const Basis power4 = Basis::parse({"power4"});
  const auto seed = lp_moment_box("unorm16", "seed", power4);
  ASSERT_TRUE(seed);
  EXPECT_EQ(seed->storage.name(), "unorm16");
  EXPECT_EQ(seed->storage.transform, unorm16_power4_storage().transform);
  EXPECT_EQ(seed->storage.offset, unorm16_power4_storage().offset);

  const auto canonical = lp_moment_box("unorm10", "canonical", power4);
  EXPECT_EQ(canonical->storage.name(), "unorm10");
  EXPECT_TRUE(canonical->storage.transform.isIdentity(1e-12));
  // Half a step and the rounding of q = b (moments/storage.h): z's row is (1, 0, 0, 0), max z = 1.
  EXPECT_NEAR(canonical->tolerance[0], 0.5 / 1023 + 8 * std::numeric_limits<double>::epsilon() * 5,
              1e-16);

  // A catalog candidate: its optimized transform is admissible and gains over its canonical one.
  const Basis candidate = Basis::parse({"z", "sin(pi z)", "z^3", "exp(z)"});
  const auto optimized = lp_moment_box("unorm16", "optimized", candidate);
  const QuantizationTransform t{optimized->storage.transform, optimized->storage.offset};
  EXPECT_LE(admissibility_violation(candidate, t), 1e-9);
  EXPECT_GT(entropy_gain_bits(candidate, t), 1.0);
  // Searched once per basis: a second box reads the first one's transform without a search.
  const size_t searched = optimized_transform_searches();
  EXPECT_EQ(lp_moment_box("unorm16", "optimized", candidate)->storage.transform,
            optimized->storage.transform);
  EXPECT_EQ(optimized_transform_searches(), searched);

  EXPECT_FALSE(lp_moment_box("none", "seed", candidate));
  EXPECT_EQ(lp_moment_box("float32", "seed", candidate)->storage.name(), "float32");
}

// Threads of a sweep ask for the optimized boxes of different bases at once: each gets its own
// basis's search (the cache's slots are per basis), the same as a search of its own.
TEST(LpMomentBox, ConcurrentOptimizedBoxesKeepTheirOwnBasis) {
  const std::vector<Basis> bases{Basis::parse({"z", "exp(-z)", "cos(pi z)"}),
                                 Basis::parse({"z^2", "sin(pi z)", "log(1+z)"})};
  std::vector<Eigen::MatrixXd> got(4);
  const size_t before = optimized_transform_searches();
  std::vector<std::thread> threads;
  for (size_t i = 0; i < got.size(); ++i)
    threads.emplace_back([&, i] {
      got[i] = lp_moment_box("unorm16", "optimized", bases[i % 2])->storage.transform;
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(optimized_transform_searches(), before + 2);  // one search per basis, not per thread
  for (size_t i = 0; i < got.size(); ++i)
    EXPECT_EQ(got[i], quantization_transform(bases[i % 2], "optimized").A) << i;
  EXPECT_NE(got[0], got[1]);
}

// A stored map's box centres on what the map holds for the fragment (FragmentInput::
// stored_values, pss_lp_stored's rounded prefix means) when given: the kernel's own stored values
// give about the bound of its texels' box, another distribution's values that distribution's.
TEST(LpMomentBox, StoredValuesCentreTheBox) {
  const Basis power4 = Basis::parse({"power4"});
  const MomentStorage storage = unorm16_power4_storage();
  TechniqueParams p;
  const auto lp = make_lp_technique("lp:power4", power4, storage, p);
  const std::vector<double> depths{0.3, 0.6}, weights{0.5, 0.5};
  std::vector<double> b(4, 0.0);
  for (size_t k = 0; k < depths.size(); ++k)
    for (int j = 0; j < 4; ++j) b[size_t(j)] += weights[k] * power4[size_t(j)](depths[k]);
  std::vector<double> q = stored_values(storage, b);
  FragmentInput in;
  in.kernel_depths = depths, in.kernel_weights = weights, in.zf = 0.5;
  const double texels = lp->shadow(in);  // the atoms stored one by one, then filtered
  in.stored_values = q;
  const double centred = lp->shadow(in);
  EXPECT_NEAR(centred, texels, 1e-3);  // two atoms' rounding moves the centre by half steps
  EXPECT_GT(centred, 0.3);             // half the mass lies in front of z_f
  EXPECT_LE(centred, 0.5 + 1e-9);
  // The stored values of another distribution (more mass in front of z_f): the bound follows
  // the centre, not the kernel.
  std::vector<double> other(4, 0.0);
  for (size_t k = 0; k < depths.size(); ++k)
    for (int j = 0; j < 4; ++j)
      other[size_t(j)] += (k == 0 ? 0.8 : 0.2) * power4[size_t(j)](depths[k]);
  const std::vector<double> moved = stored_values(storage, other);
  in.stored_values = moved;
  EXPECT_GT(lp->shadow(in), centred + 0.2);
  EXPECT_EQ(lp->failures(), 0u);
}

TEST(LpMomentBox, RefusesSeedWithoutATransformAndUnknownFormats) {
  const Basis trig4 = Basis::parse({"trig4"});
  try {
    lp_moment_box("unorm16", "seed", trig4);
    FAIL() << "seed accepted for trig4";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("lp.moment_transform: seed"), std::string::npos) << what;
    EXPECT_NE(what.find("canonical or optimized"), std::string::npos) << what;
  }
  for (const char* bad : {"unorm12", "unorm", "unorm1x", "snorm16"})
    EXPECT_THROW(lp_moment_box(bad, "canonical", trig4), InputError) << bad;
}

// Two sweeps that differ only in lp.moment_transform measure different things: neither a resume
// nor a merge may join them, and one written before the option existed counts as seed.
TEST(LpMomentBox, TheTransformIsPartOfASweepsIdentity) {
  // What `sweep` and `merge` compare (cmd/sweep_command.cpp, sweep_specs).
  std::vector<OptionSpec> specs = shadow_option_specs();
  for (auto& s : sweep_option_specs()) specs.push_back(s);
  const std::string before = "dataset: tiny\nlp.moment_box: unorm16\n";
  const std::string seed = before + "lp.moment_transform: seed\n";
  const std::string optimized = before + "lp.moment_transform: optimized\n";
  EXPECT_NE(config_hash(seed, specs), config_hash(optimized, specs));
  const auto d = config_differences(Meta{{"config", seed}}, optimized, specs);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].key, "lp.moment_transform");
  EXPECT_TRUE(config_differences(Meta{{"config", before}}, seed, specs).empty());
  EXPECT_EQ(config_differences(Meta{{"config", before}}, optimized, specs).size(), 1u);
  EXPECT_EQ(measurement_differences(measurement_meta(seed, specs),
                                    measurement_meta(optimized, specs), specs)
                .size(),
            1u);
}

}  // namespace
}  // namespace mb
