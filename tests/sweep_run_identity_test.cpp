// Run identity: the config hash sees option values only, so documentation can change without
// making a sweep unresumable, while any changed value still refuses a resume or a merge.
#include <gtest/gtest.h>

#include "sweep/run_identity.h"

namespace mb {
namespace {

const std::string kYaml =
    "# Dataset: a YAML file.\ndataset: tiny\n# OpenMP threads.\nthreads: 0\n# Grid.\nlp.grid: "
    "256\n";

TEST(RunIdentity, HashIgnoresCommentsAndThreads) {
  const std::string reworded =
      "# Dataset: reworded prose.\ndataset: tiny\n# Threads.\nthreads: 7\n# Grid points.\nlp.grid: "
      "256\n";
  EXPECT_EQ(config_hash(kYaml), config_hash(reworded));
  EXPECT_EQ(config_values(kYaml), "dataset: tiny\nlp.grid: 256\n");
}

TEST(RunIdentity, AnyValueChangesTheHash) {
  const std::string other = "# Dataset.\ndataset: tiny\nthreads: 0\nlp.grid: 257\n";
  EXPECT_NE(config_hash(kYaml), config_hash(other));
  EXPECT_FALSE(same_config({{"config_hash", config_hash(other)}, {"config", other}}, kYaml));
}

TEST(RunIdentity, DatabasesWithTheOlderHashAreRecognisedByTheirValues) {
  // Before the value-only hash, the hash covered the comments too: a reworded doc changed it.
  const std::map<std::string, std::string> legacy{{"config_hash", "086f6f348efb6a84"},
                                                  {"config", "# Old prose.\n" + kYaml}};
  EXPECT_TRUE(same_config(legacy, kYaml));
  EXPECT_FALSE(same_config(legacy, "dataset: default\nlp.grid: 256\n"));
}

// A sweep begun before an option existed resumes when the option is at its default (which keeps the
// old behaviour), and not when it was changed.
TEST(RunIdentity, OptionsAddedSinceCountAtTheirDefault) {
  const std::map<std::string, std::string> old{{"config_hash", "0000000000000000"},
                                               {"config", kYaml}};
  const std::string defaults = "dataset: default\nthreads: 0\nlp.grid: 256\nesm.threshold: 0.01\n";
  const std::string now = kYaml + "# New.\nesm.threshold: 0.01\n";
  EXPECT_TRUE(same_config(old, now, defaults));
  EXPECT_FALSE(same_config(old, now));  // without the defaults, a new key is a difference
  EXPECT_FALSE(same_config(old, kYaml + "esm.threshold: 0.5\n", defaults));
  EXPECT_FALSE(same_config(old, "dataset: tiny\n",
                           defaults));  // a key removed  // a key removed is a difference
}

TEST(RunIdentity, MeasurementKeysHoldExactValues) {
  EvalSettings settings;
  settings.technique.lp.grid = 300;
  settings.technique.lp.lo = 0.1;
  settings.technique.lp.hi = 0.30000000000000004;  // %g would print 0.3
  auto meta = measurement_meta(settings);
  meta["dataset"] = "tiny";
  const auto grid = lp_grid_of(meta);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->grid, 300);
  EXPECT_EQ(grid->lo, 0.1);
  EXPECT_EQ(grid->hi, 0.30000000000000004);
  EXPECT_EQ(incomparable_key(meta, meta), "");
  auto other = meta;
  other["lp.hi"] = "0.3";
  EXPECT_EQ(incomparable_key(meta, other), "lp.hi");
  other = meta;
  other["dataset"] = "default";
  EXPECT_EQ(incomparable_key(meta, other), "dataset");
}

// Databases from before the measurement keys: the settings sentence decides, and the LP grid is
// read back out of it.
TEST(RunIdentity, OlderDatabasesAreReadFromTheirSettingsSentence) {
  const std::map<std::string, std::string> old{
      {"dataset", "tiny"},
      {"reference", "biased"},
      {"settings",
       "kernel 9x9 Gaussian, sigma 2.4 texels; reference biased; LP grid 256 on [0, "
       "1], backend fast"}};
  const auto grid = lp_grid_of(old);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->grid, 256);
  EXPECT_EQ(grid->hi, 1);
  EXPECT_EQ(incomparable_key(old, old), "");
  auto other = old;
  other["settings"] =
      "kernel 9x9 Gaussian, sigma 2.4 texels; reference biased; LP grid 512 on [0, 1]";
  EXPECT_EQ(incomparable_key(old, other), "settings");
  EXPECT_FALSE(lp_grid_of({{"dataset", "tiny"}}));
}

}  // namespace
}  // namespace mb
