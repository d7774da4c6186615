// Run identity (docs/sweeps.md "Identity"): the option records say which options make a run what
// it is. The config hash sees option values only and leaves out the options that change no
// measured number (threads); a resume or merge names every other differing option; a report
// compares every measurement option, reading older databases through their stored config, their
// twelve measurement keys or their settings sentence.
#include <gtest/gtest.h>

#include "sweep/run_identity.h"

namespace mb {
namespace {

// A small option table: one option of each effect and two measurement options.
const std::vector<OptionSpec>& specs() {
  static const std::vector<OptionSpec> s{
      {"dataset", OptionType::String, "default", "Dataset."},
      measures_nothing({"threads", OptionType::Integer, "0", "Threads."}),
      {"lp.grid", OptionType::Integer, "256", "Grid."},
      {"light.angle", OptionType::Number, "0", "Area light."},
      selects_runs({"sample", OptionType::Integer, "0", "Sample."}),
  };
  return s;
}

const std::string kYaml =
    "# Dataset: a YAML file.\ndataset: tiny\n# OpenMP threads.\nthreads: 0\n# Grid.\nlp.grid: "
    "256\n# Area light.\nlight.angle: 0\nsample: 0\n";

TEST(RunIdentity, HashIgnoresCommentsAndOptionsThatMeasureNothing) {
  const std::string reworded =
      "# Dataset: reworded prose.\ndataset: tiny\n# Threads.\nthreads: 7\n# Grid points.\nlp.grid: "
      "256\nlight.angle: 0\nsample: 0\n";
  EXPECT_EQ(config_hash(kYaml, specs()), config_hash(reworded, specs()));
  EXPECT_EQ(config_values(kYaml, specs()),
            "dataset: tiny\nlp.grid: 256\nlight.angle: 0\nsample: 0\n");
  // The same config with threads declared as measuring: then threads is part of the hash.
  std::vector<OptionSpec> measuring = specs();
  measuring[1].effect = OptionEffect::Measures;
  EXPECT_NE(config_hash(kYaml, measuring), config_hash(reworded, measuring));
}

TEST(RunIdentity, AResumeNamesEveryDifferingOptionButThreads) {
  const Meta stored{{"config_hash", config_hash(kYaml, specs())}, {"config", kYaml}};
  std::string now = kYaml;
  now.replace(now.find("threads: 0"), 10, "threads: 3");
  EXPECT_TRUE(same_config(stored, now, specs()));
  now.replace(now.find("light.angle: 0"), 14, "light.angle: 3");
  now.replace(now.find("sample: 0"), 9, "sample: 8");
  const auto d = config_differences(stored, now, specs());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].key, "light.angle");
  EXPECT_EQ(d[0].first, "0");
  EXPECT_EQ(d[0].second, "3");
  EXPECT_EQ(d[1].key, "sample");
  EXPECT_EQ(differences_text(d, "that sweep", "this one"),
            "light.angle is 0 in that sweep, 3 in this one; sample is 0 in that sweep, 8 in this "
            "one");
}

TEST(RunIdentity, DatabasesWithTheOlderHashAreRecognisedByTheirValues) {
  // Before the value-only hash, the hash covered the comments too: a reworded doc changed it.
  const Meta legacy{{"config_hash", "086f6f348efb6a84"}, {"config", "# Old prose.\n" + kYaml}};
  EXPECT_TRUE(same_config(legacy, kYaml, specs()));
  EXPECT_FALSE(
      same_config(legacy, "dataset: default\nlp.grid: 256\nlight.angle: 0\nsample: 0\n", specs()));
}

// A sweep begun before an option existed resumes when the option is at its default (which keeps the
// old behaviour), and not when it was changed; an option the stored config has and the table no
// longer declares is a difference.
TEST(RunIdentity, OptionsAddedSinceCountAtTheirDefault) {
  const std::string before = "dataset: tiny\nthreads: 0\nlp.grid: 256\nsample: 0\n";
  const Meta old{{"config_hash", "0000000000000000"}, {"config", before}};
  EXPECT_TRUE(same_config(old, kYaml, specs()));
  std::string changed = kYaml;
  changed.replace(changed.find("light.angle: 0"), 14, "light.angle: 0.5");
  const auto d = config_differences(old, changed, specs());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].key, "light.angle");
  EXPECT_EQ(d[0].first, "0");
  const Meta removed{{"config", before + "esm.threshold: 0.5\n"}};
  EXPECT_FALSE(same_config(removed, kYaml, specs()));
}

// merge compares two stored configs: one written before an option existed agrees with one that has
// it at its default, whichever shard comes first.
TEST(RunIdentity, AnOptionAddedSinceCountsAtItsDefaultOnEitherSide) {
  const std::string before = "dataset: tiny\nthreads: 0\nlp.grid: 256\nsample: 0\n";
  const Meta older{{"config", before}}, newer{{"config", kYaml}};
  EXPECT_TRUE(config_differences(older, kYaml, specs()).empty());
  EXPECT_TRUE(config_differences(newer, before, specs()).empty());
  std::string changed = kYaml;
  changed.replace(changed.find("light.angle: 0"), 14, "light.angle: 2");
  EXPECT_EQ(config_differences(Meta{{"config", changed}}, before, specs()).size(), 1u);
  EXPECT_EQ(config_differences(older, changed, specs()).size(), 1u);
}

TEST(RunIdentity, MeasurementMetaHoldsEveryMeasurementOption) {
  const Meta meta = measurement_meta(kYaml, specs());
  EXPECT_EQ(meta, (Meta{{"dataset", "tiny"}, {"lp.grid", "256"}, {"light.angle", "0"}}));
  EXPECT_TRUE(measurement_differences(meta, meta, specs()).empty());
  Meta other = meta;
  other["light.angle"] = "3";
  other["dataset"] = "default";
  const auto d = measurement_differences(other, meta, specs());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].key, "dataset");  // first, whatever the table's order
  EXPECT_EQ(d[1].key, "light.angle");
  EXPECT_EQ(d[1].first, "3");
  EXPECT_EQ(d[1].second, "0");
}

// Databases from before every measurement option was stored (the twelve keys and the config): a
// key they lack is read from their stored config, then taken at its default.
TEST(RunIdentity, OlderDatabasesAreReadThroughTheirStoredConfig) {
  const Meta twelve{{"dataset", "tiny"},
                    {"lp.grid", "256"},
                    {"lp.lo", "0"},
                    {"lp.hi", "0.30000000000000004"},
                    {"config", "dataset: tiny\nlp.grid: 256\nlight.angle: 3\n"}};
  const Meta now = measurement_meta(kYaml, specs());
  EXPECT_EQ(measurement_value(twelve, "light.angle", specs()), "3");
  const auto d = measurement_differences(twelve, now, specs());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].key, "light.angle");
  Meta without_config = twelve;
  without_config.erase("config");  // the option's default, the behaviour before it existed
  EXPECT_TRUE(measurement_differences(without_config, now, specs()).empty());
  const auto grid = lp_grid_of(twelve);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->grid, 256);
  EXPECT_EQ(grid->hi, 0.30000000000000004);
}

// Databases from before the measurement keys: the settings sentence decides too, and the LP grid is
// read back out of it.
TEST(RunIdentity, OldestDatabasesAreReadFromTheirSettingsSentence) {
  const Meta old{{"dataset", "tiny"},
                 {"settings",
                  "kernel 9x9 Gaussian, sigma 2.4 texels; reference biased; LP grid 256 on [0, "
                  "1], backend fast"}};
  const auto grid = lp_grid_of(old);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->grid, 256);
  EXPECT_EQ(grid->hi, 1);
  EXPECT_TRUE(measurement_differences(old, old, specs()).empty());
  Meta other = old;
  other["settings"] =
      "kernel 9x9 Gaussian, sigma 2.4 texels; reference biased; LP grid 512 on [0, 1]";
  const auto d = measurement_differences(old, other, specs());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].key, "settings");
  EXPECT_FALSE(lp_grid_of({{"dataset", "tiny"}}));
}

}  // namespace
}  // namespace mb
