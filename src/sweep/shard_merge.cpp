#include "sweep/shard_merge.h"

#include <map>
#include <set>

#include "sweep/sweep_plan.h"
#include "util/error.h"

namespace mb {

ShardSet check_shards(const std::vector<std::string>& shards, const std::vector<OptionSpec>& specs,
                      bool partial) {
  ShardSet set;
  for (const auto& s : shards) set.stores.push_back(ResultsStore::open(results_database_path(s)));
  Meta first = set.stores[0].meta();
  std::map<uint64_t, std::string> owner, screened;
  std::set<std::string> shard_names;
  for (size_t i = 0; i < set.stores.size(); ++i) {
    Meta meta = set.stores[i].meta();
    if (const auto differences = config_differences(meta, first["config"], specs);
        !differences.empty())
      throw InputError(shards[i] + ": config hash " + meta["config_hash"] + " differs from " +
                       shards[0] + "'s " + first["config_hash"] + " (" +
                       differences_text(differences, shards[i], shards[0]) +
                       "): not shards of one sweep");
    if (!shard_names.insert(meta["shard"]).second)
      throw InputError(shards[i] + ": shard " + meta["shard"] + " is given twice");
    // Candidates, and a screened sweep's estimates (sweep --screen), each in one shard only.
    auto claim = [&](std::map<uint64_t, std::string>& owners, const std::set<uint64_t>& ids,
                     const char* what) {
      for (uint64_t id : ids) {
        auto [it, fresh] = owners.emplace(id, shards[i]);
        if (!fresh)
          throw InputError(what + std::to_string(id) + " is in both " + it->second + " and " +
                           shards[i] + ": overlapping shards");
      }
    };
    claim(owner, set.stores[i].candidate_ids(), "candidate ");
    claim(screened, set.stores[i].estimate_ids(1), "the estimate of candidate ");
  }
  // Every shard of K/N must be there, or the merged sweep silently lacks candidates.
  const int total_shards = parse_shard(first["shard"]).second;
  for (int k = 1; k <= total_shards; ++k) {
    const std::string name = std::to_string(k) + "/" + std::to_string(total_shards);
    if (!shard_names.count(name)) set.missing += (set.missing.empty() ? "" : ", ") + name;
  }
  for (const auto& name : shard_names)
    if (parse_shard(name).second != total_shards)
      throw InputError("shard " + name + " and shard " + first["shard"] +
                       " split the sweep differently");
  if (!set.missing.empty() && !partial)
    throw InputError("shards " + set.missing +
                     " of this sweep are missing; give every shard, or --partial to merge "
                     "these alone");
  for (const auto& s : shard_names) set.merged += (set.merged.empty() ? "" : ", ") + s;
  set.meta = first;
  set.meta["shard"] = "1/1";
  set.meta["merged_from"] = set.merged;
  if (!set.missing.empty()) set.meta["missing_shards"] = set.missing;
  set.candidates = owner.size(), set.screened = screened.size();
  return set;
}

void write_merged_results(ShardSet& shards, const std::string& path) {
  ResultsStore target = ResultsStore::create(path, shards.meta);
  target.batch([&] {
    for (const auto& r : shards.stores[0].references()) target.put_reference(r);
    for (auto& input : shards.stores) {
      for (const auto& r : input.candidates()) target.put_candidate(r);
      for (const auto& r : input.estimates(0)) target.put_estimate(r);
    }
  });
}

}  // namespace mb
