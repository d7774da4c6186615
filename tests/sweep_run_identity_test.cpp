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

}  // namespace
}  // namespace mb
