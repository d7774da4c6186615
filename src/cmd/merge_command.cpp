// `momentbench merge`: shard databases of one sweep -> one database (issue 5). Refuses shards
// of different configs and shards that overlap (a candidate in two of them).
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/results_store.h"
#include "util/error.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct MergeOptions {
  std::vector<std::string> shards;
  std::string out;
  bool force = false;
};

std::string database_of(const std::string& dir) {
  return std::filesystem::is_directory(dir) ? (std::filesystem::path(dir) / "results.sqlite").string() : dir;
}

int run_merge(const MergeOptions& o) {
  std::vector<ResultsStore> inputs;
  for (const auto& s : o.shards) inputs.push_back(ResultsStore::open(database_of(s)));
  auto first = inputs[0].meta();
  std::map<uint64_t, std::string> owner;
  std::set<std::string> shard_names;
  for (size_t i = 0; i < inputs.size(); ++i) {
    auto meta = inputs[i].meta();
    if (meta["config_hash"] != first["config_hash"])
      throw InputError(o.shards[i] + ": config hash " + meta["config_hash"] + " differs from " + o.shards[0] + "'s " +
                       first["config_hash"] + ": not shards of one sweep");
    if (!shard_names.insert(meta["shard"]).second)
      throw InputError(o.shards[i] + ": shard " + meta["shard"] + " is given twice");
    for (uint64_t id : inputs[i].candidate_ids()) {
      auto [it, fresh] = owner.emplace(id, o.shards[i]);
      if (!fresh)
        throw InputError("candidate " + std::to_string(id) + " is in both " + it->second + " and " + o.shards[i] +
                         ": overlapping shards");
    }
  }
  StagedOutputDir out(o.out, o.force);
  auto meta = first;
  meta["shard"] = "1/1";
  std::string merged;
  for (const auto& s : shard_names) merged += (merged.empty() ? "" : ", ") + s;
  meta["merged_from"] = merged;
  {
    ResultsStore target = ResultsStore::create((out / "results.sqlite").string(), meta);
    for (const auto& r : inputs[0].references()) target.put_reference(r);
    for (auto& input : inputs)
      for (const auto& r : input.candidates()) target.put_candidate(r);
  }
  write_file_atomically(out / "config.yaml", first["config"]);
  out.commit();
  std::printf("merged %zu shards (%s): %zu candidates -> %s\n", inputs.size(), merged.c_str(), owner.size(),
              o.out.c_str());
  return 0;
}

}  // namespace

void register_merge_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* command = app.add_subcommand("merge", "Combine the shard databases of one sweep");
  command->add_option("shards", options->shards, "Shard output directories (or results.sqlite files)")->required();
  command->add_option("-o,--out", options->out, "Output directory (must not exist, unless --force)")->required();
  command->add_flag("-f,--force", options->force, "Replace an existing output directory");
  command->callback([options, &action] { action = [options] { return run_merge(*options); }; });
}

}  // namespace mb
