// `momentbench merge`: shard databases of one sweep -> one database (issue 5). Refuses shards
// of different configs and shards that overlap (a candidate in two of them): sweep/shard_merge.h.
#include <cstdio>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "sweep/shard_merge.h"
#include "util/error.h"
#include "util/option_record.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct MergeOptions {
  std::vector<std::string> shards;
  bool partial = false;
};

const std::vector<OptionRecord<MergeOptions>>& merge_options() {
  static const std::vector<OptionRecord<MergeOptions>> records{
      {measures_nothing(
           {"partial", OptionType::Boolean, "false",
            "Merge even when some shards of the sweep are missing (the report names them)."}),
       &MergeOptions::partial},
  };
  return records;
}

int run_merge(const CLI::App& command, const CommonOptions& common, const MergeOptions& flags) {
  auto cmd =
      CommandRun::begin(merge_specs(), common, command,
                        {{"--partial", "partial", [&] { return YAML::Node(flags.partial); }}});
  if (!cmd) return 0;
  MergeOptions o = flags;
  read_options(cmd->config(), merge_options(), o);
  if (o.shards.empty()) throw InputError("merge: give the shards' output directories");
  if (common.out.empty()) throw InputError("merge: --out DIR is required");
  ShardSet shards = check_shards(o.shards, sweep_specs(), o.partial);
  StagedOutputDir& out = cmd->out();
  write_merged_results(shards, (out / "results.sqlite").string());
  write_file_atomically(out / "config.yaml", shards.meta.at("config"));
  out.commit();
  std::printf("merged %zu shards (%s): %zu candidates%s -> %s%s\n", shards.stores.size(),
              shards.merged.c_str(), shards.candidates,
              shards.screened ? (", " + std::to_string(shards.screened) + " screened").c_str() : "",
              common.out.c_str(),
              shards.missing.empty() ? "" : ("; missing shards " + shards.missing).c_str());
  return 0;
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
    action = [options, common, command] { return run_merge(*command, *common, *options); };
  });
}

}  // namespace mb
