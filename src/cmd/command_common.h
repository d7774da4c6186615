#pragma once
// What every subcommand shares: --config, --set, --print-config, --out, --force, --quiet, and
// turning them into a validated Config (docs/design.md §Commands).
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/dataset_options.h"
#include "util/config.h"
#include "util/number_text.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"

namespace mb {

struct CommonOptions {
  std::string config_file;
  std::vector<std::string> sets;
  bool print_config = false;
  std::string out;
  bool force = false;
  bool quiet = false;
};

void add_common_options(CLI::App& command, CommonOptions& options, bool has_output = true);
// --print-config: prints the effective config as YAML that --config reads back; true when it did
// (the command then stops).
bool print_config_if_asked(const Config& config, const CommonOptions& options);
// config.yaml (the effective config, which --config reads back) and run.yaml (how it was run)
// into an output directory, written atomically.
void write_run_record(const StagedOutputDir& out, const Config& config, const RunMetadata& meta);
// Defaults, then the config file, then every --set in order.
Config resolve_config(std::vector<OptionSpec> specs, const CommonOptions& options);

// A command's own flags as shorthands of option keys: each flag given on the command line sets its
// key after the config file and every --set (a list flag gives a list; a flag without a value
// gives true, or false for a "!--no-x" flag), so --print-config shows it and it is validated
// like --set.
struct FlagKey {
  std::string flag;                   // as registered, e.g. "--grid"
  std::string key;                    // the option key, e.g. "grid"
  std::function<YAML::Node()> value;  // the flag's parsed value, as YAML
};
void apply_flags(const CLI::App& command, Config& config, const std::vector<FlagKey>& flags);

// One run of a command that writes an output directory, the prologue and epilogue every such
// command shares (docs/design.md §Commands): the resolved config and thread count first, the staged
// output directory only once the command has checked its input (bad input leaves no output), and
// at the end config.yaml, run.yaml and the atomic commit (or, for a command that records its run
// otherwise, out().commit()).
class CommandRun {
 public:
  // resolve_config, then the command's own `flags` (apply_flags); nullopt when --print-config
  // printed the config (the command then stops).
  static std::optional<CommandRun> begin(std::vector<OptionSpec> specs,
                                         const CommonOptions& options);
  static std::optional<CommandRun> begin(std::vector<OptionSpec> specs,
                                         const CommonOptions& options, const CLI::App& command,
                                         const std::vector<FlagKey>& flags);
  const Config& config() const { return config_; }
  // The `threads` option resolved (0: every core); 1 for a command without one.
  int threads() const { return threads_; }
  // The staged output directory, made on first use.
  StagedOutputDir& out();
  // This run's metadata, collected on first use.
  const RunMetadata& metadata();
  // config.yaml and run.yaml into the output directory, then its commit.
  void finish();

 private:
  CommandRun(Config config, const CommonOptions& options);
  Config config_;
  const CommonOptions* options_;
  int threads_ = 1;
  std::unique_ptr<StagedOutputDir> out_;
  std::optional<RunMetadata> metadata_;
};

// The argv of this process, for run metadata.
const std::vector<std::string>& process_arguments();
void set_process_arguments(int argc, char** argv);

// Option declarations shared by the commands that read a dataset.
std::vector<OptionSpec> dataset_option_specs();

// Runs scripts/<script> (found by data_root(), util/install_paths.h) with its arguments, no shell,
// with Debian's /usr/bin/python3 when matplotlib is there (docs/design.md §Style: plots
// stay in Python). Returns the Markdown line for the report: the image `<out_stem>.png` (and
// .pdf), or a note saying why there is no plot. InputError when the script itself fails.
std::string run_plot_script(const std::string& script, std::vector<std::string> arguments,
                            const std::string& out_stem, const std::string& caption, bool quiet);

}  // namespace mb
