#pragma once
// `merge`'s checks and its database (docs/sweeps.md): the shard databases of one sweep
// become one, refused when they are not shards of one sweep, overlap, or leave a shard out.
#include <string>
#include <vector>

#include "sweep/results_store.h"
#include "sweep/run_identity.h"
#include "util/config.h"

namespace mb {

struct ShardSet {
  std::vector<ResultsStore> stores;  // in the order given
  Meta meta;                         // the merged database's: shard 1/1, merged_from, ...
  std::string merged;                // the shards given, "1/3, 2/3"
  std::string missing;               // the shards of K/N not given, "" when none
  size_t candidates = 0, screened = 0;
};

// Opens `shards` (output directories or their results.sqlite) and checks that they merge: one
// configuration (config_differences under `specs`), each shard once, one split K/N, no candidate
// and no screened estimate in two of them, and every shard of K/N unless `partial`. InputError
// naming the shards and the difference otherwise.
ShardSet check_shards(const std::vector<std::string>& shards, const std::vector<OptionSpec>& specs,
                      bool partial);
// The merged database at `path`: the first shard's references, every shard's candidates and
// estimates.
void write_merged_results(ShardSet& shards, const std::string& path);

}  // namespace mb
