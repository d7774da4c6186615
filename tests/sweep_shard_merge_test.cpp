// `merge`'s checks (sweep/shard_merge.h): shards of one sweep merge into one database; a shard
// given twice, a candidate in two shards and a missing shard are refused (the last one unless
// partial).
#include <gtest/gtest.h>

#include <filesystem>

#include "sweep/shard_merge.h"
#include "util/error.h"

namespace mb {
namespace {

class ShardMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("momentbench_shard_merge_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A shard's database holding candidates `ids`; returns its path.
  std::string shard(const std::string& name, const std::string& shard,
                    const std::vector<uint64_t>& ids) {
    const std::string path = (dir_ / (name + ".sqlite")).string();
    ResultsStore store = ResultsStore::create(
        path, {{"config", "sample: 4\n"}, {"config_hash", "h"}, {"shard", shard}});
    for (uint64_t id : ids) {
      ResultRow row;
      row.id = id, row.name = "candidate " + std::to_string(id), row.mean = 0.01 * double(id);
      store.put_candidate(row);
    }
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(ShardMerge, TwoShardsBecomeOneDatabase) {
  ShardSet set = check_shards({shard("a", "1/2", {1, 3}), shard("b", "2/2", {2, 4})}, {}, false);
  EXPECT_EQ(set.candidates, 4u);
  EXPECT_EQ(set.merged, "1/2, 2/2");
  EXPECT_EQ(set.missing, "");
  EXPECT_EQ(set.meta.at("shard"), "1/1");
  EXPECT_EQ(set.meta.at("merged_from"), "1/2, 2/2");
  const std::string merged = (dir_ / "merged.sqlite").string();
  write_merged_results(set, merged);
  EXPECT_EQ(ResultsStore::open(merged).candidate_ids(), (std::set<uint64_t>{1, 2, 3, 4}));
}

TEST_F(ShardMerge, OverlapsRepeatsAndMissingShardsAreRefused) {
  EXPECT_THROW(check_shards({shard("a", "1/2", {1, 2}), shard("b", "2/2", {2})}, {}, false),
               InputError);
  EXPECT_THROW(check_shards({shard("c", "1/2", {1}), shard("d", "1/2", {2})}, {}, false),
               InputError);
  const std::string alone = shard("e", "1/3", {1});
  EXPECT_THROW(check_shards({alone}, {}, false), InputError);
  const ShardSet partial = check_shards({alone}, {}, true);
  EXPECT_EQ(partial.missing, "2/3, 3/3");
  EXPECT_EQ(partial.meta.at("missing_shards"), "2/3, 3/3");
}

}  // namespace
}  // namespace mb
