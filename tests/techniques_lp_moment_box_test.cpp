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
  // Searched once per basis: a second box reads the same transform.
  EXPECT_EQ(lp_moment_box("unorm16", "optimized", candidate)->storage.transform,
            optimized->storage.transform);

  EXPECT_FALSE(lp_moment_box("none", "seed", candidate));
  EXPECT_EQ(lp_moment_box("float32", "seed", candidate)->storage.name(), "float32");
}

// Threads of a sweep ask for the optimized boxes of different bases at once: each gets its own
// basis's search (the cache's slots are per basis), the same as a search of its own.
TEST(LpMomentBox, ConcurrentOptimizedBoxesKeepTheirOwnBasis) {
  const std::vector<Basis> bases{Basis::parse({"z", "exp(-z)", "cos(pi z)"}),
                                 Basis::parse({"z^2", "sin(pi z)", "log(1+z)"})};
  std::vector<Eigen::MatrixXd> got(4);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < got.size(); ++i)
    threads.emplace_back([&, i] {
      got[i] = lp_moment_box("unorm16", "optimized", bases[i % 2])->storage.transform;
    });
  for (auto& t : threads) t.join();
  for (size_t i = 0; i < got.size(); ++i)
    EXPECT_EQ(got[i], quantization_transform(bases[i % 2], "optimized").A) << i;
  EXPECT_NE(got[0], got[1]);
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
