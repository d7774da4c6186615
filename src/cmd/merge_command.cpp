// `momentbench merge`: shard databases of one sweep -> one database (issue 5). Refuses shards
// of different configs and shards that overlap (a candidate in two of them).
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "sweep/results_store.h"
#include "sweep/run_identity.h"
#include "sweep/sweep_plan.h"
#include "util/error.h"
#include "util/option_record.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct MergeOptions {
  std::vector<std::string> shards;
  std::string out;
  bool force = false, partial = false;
};

int run_merge(const MergeOptions& o) {
  std::vector<ResultsStore> inputs;
  for (const auto& s : o.shards) inputs.push_back(ResultsStore::open(results_database_path(s)));
  auto first = inputs[0].meta();
  std::map<uint64_t, std::string> owner, screened;
  std::set<std::string> shard_names;
  for (size_t i = 0; i < inputs.size(); ++i) {
    auto meta = inputs[i].meta();
    if (const auto differences = config_differences(meta, first["config"], sweep_specs());
        !differences.empty())
      throw InputError(o.shards[i] + ": config hash " + meta["config_hash"] + " differs from " +
                       o.shards[0] + "'s " + first["config_hash"] + " (" +
                       differences_text(differences, o.shards[i], o.shards[0]) +
                       "): not shards of one sweep");
    if (!shard_names.insert(meta["shard"]).second)
      throw InputError(o.shards[i] + ": shard " + meta["shard"] + " is given twice");
    // Candidates, and a screened sweep's estimates (sweep --screen), each in one shard only.
    auto claim = [&](std::map<uint64_t, std::string>& owners, const std::set<uint64_t>& ids,
                     const char* what) {
      for (uint64_t id : ids) {
        auto [it, fresh] = owners.emplace(id, o.shards[i]);
        if (!fresh)
          throw InputError(what + std::to_string(id) + " is in both " + it->second + " and " +
                           o.shards[i] + ": overlapping shards");
      }
    };
    claim(owner, inputs[i].candidate_ids(), "candidate ");
    claim(screened, inputs[i].estimate_ids(1), "the estimate of candidate ");
  }
  // Every shard of K/N must be there, or the merged sweep silently lacks candidates.
  const auto [first_k, total_shards] = parse_shard(first["shard"]);
  (void)first_k;
  std::string missing;
  for (int k = 1; k <= total_shards; ++k) {
    const std::string name = std::to_string(k) + "/" + std::to_string(total_shards);
    if (!shard_names.count(name)) missing += (missing.empty() ? "" : ", ") + name;
  }
  for (const auto& name : shard_names)
    if (parse_shard(name).second != total_shards)
      throw InputError("shard " + name + " and shard " + first["shard"] +
                       " split the sweep differently");
  if (!missing.empty() && !o.partial)
    throw InputError("shards " + missing +
                     " of this sweep are missing; give every shard, or --partial to merge "
                     "these alone");
  StagedOutputDir out(o.out, o.force);
  auto meta = first;
  meta["shard"] = "1/1";
  std::string merged;
  for (const auto& s : shard_names) merged += (merged.empty() ? "" : ", ") + s;
  meta["merged_from"] = merged;
  if (!missing.empty()) meta["missing_shards"] = missing;
  {
    ResultsStore target = ResultsStore::create((out / "results.sqlite").string(), meta);
    target.batch([&] {
      for (const auto& r : inputs[0].references()) target.put_reference(r);
      for (auto& input : inputs) {
        for (const auto& r : input.candidates()) target.put_candidate(r);
        for (const auto& r : input.estimates(0)) target.put_estimate(r);
      }
    });
  }
  write_file_atomically(out / "config.yaml", first["config"]);
  out.commit();
  std::printf(
      "merged %zu shards (%s): %zu candidates%s -> %s%s\n", inputs.size(), merged.c_str(),
      owner.size(),
      screened.empty() ? "" : (", " + std::to_string(screened.size()) + " screened").c_str(),
      o.out.c_str(), missing.empty() ? "" : ("; missing shards " + missing).c_str());
  return 0;
}

}  // namespace

namespace {

const std::vector<OptionRecord<MergeOptions>>& merge_options() {
  static const std::vector<OptionRecord<MergeOptions>> records{
      {measures_nothing(
           {"partial", OptionType::Boolean, "false",
            "Merge even when some shards of the sweep are missing (the report names them)."}),
       &MergeOptions::partial},
  };
  return records;
}

}  // namespace

std::vector<OptionSpec> merge_specs() {
  return option_specs(merge_options());
}

void register_merge_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<MergeOptions>();
  auto common = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand("merge", "Combine the shard databases of one sweep");
  add_common_options(*command, *common);
  command->add_option("shards", options->shards,
                      "Shard output directories (or results.sqlite files)");
  command->add_flag("--partial", options->partial, "= --set partial=true");
  command->callback([options, common, command, &action] {
    action = [options, common, command] {
      Config config = resolve_config(merge_specs(), *common);
      apply_flags(*command, config,
                  {{"--partial", "partial", [&] { return YAML::Node(options->partial); }}});
      if (print_config_if_asked(config, *common)) return 0;
      MergeOptions o = *options;
      o.out = common->out, o.force = common->force;
      read_options(config, merge_options(), o);
      if (o.shards.empty()) throw InputError("merge: give the shards' output directories");
      if (o.out.empty()) throw InputError("merge: --out DIR is required");
      return run_merge(o);
    };
  });
}

}  // namespace mb
