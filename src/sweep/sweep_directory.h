#pragma once
// A sweep's output directory is its state (README "Sweeps: resume, shards, clusters"): a new
// sweep creates it with config.yaml and an atomically created results database; a resumed one
// must hold the same config and shard; a directory killed before its database existed is started
// afresh, and anything else is refused.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sweep/results_store.h"
#include "util/config.h"

namespace mb {

struct SweepIdentity {
  std::string config_hash;        // equal hashes resume at once; else config_differences decides
  std::string shard;              // "K/N"
  std::string config_yaml;        // written to config.yaml and into the database's meta
  std::vector<OptionSpec> specs;  // every option: which a resume compares (run_identity.h)
};

// The results database of the sweep in `out`: opened when resuming one with the same identity,
// otherwise created (with `identity` and `meta` in its meta table). InputError when `out` holds
// another sweep, or files that are not a sweep's, or exists without --resume or --force.
ResultsStore open_sweep_directory(const std::filesystem::path& out, const SweepIdentity& identity,
                                  const std::map<std::string, std::string>& meta, bool resume,
                                  bool force);

}  // namespace mb
